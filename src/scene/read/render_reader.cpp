// Reading render settings; see render_reader.h.
#include "scene/read/render_reader.h"

#include <cstdint>

#include "scene/read/did_you_mean.h"

namespace candela {

void readRender(const JsonValue& value, RenderSettings& render, OutputDesc& output) {
  JsonObject fields(value, {"max_depth", "integrator", "light_paths", "antialiasing", "seed",
                            "gamma", "exposure", "tone_map"});
  if (std::optional<JsonValue> depth = fields.get("max_depth"))
    render.maxDepth = static_cast<uint32_t>(depth->integer(1, UINT32_MAX, "a positive integer"));
  if (std::optional<JsonValue> integrator = fields.get("integrator"))
    render.integrator =
        integrator->choice({"path", "direct"}) == 0 ? IntegratorType::Path : IntegratorType::Direct;
  if (std::optional<JsonValue> lightPaths = fields.get("light_paths"))
    render.lightPaths = LightPaths(lightPaths->choice({"auto", "on", "off"}));
  if (std::optional<JsonValue> antialiasing = fields.get("antialiasing"))
    render.antialiasing = antialiasing->boolean();
  if (std::optional<JsonValue> seed = fields.get("seed"))
    render.seed = seed->integer(0, UINT64_MAX, "a non-negative integer");

  if (std::optional<JsonValue> gamma = fields.get("gamma")) {
    const std::string expectation = "a positive number or \"srgb\"";
    if (gamma->json().is_string()) {
      const std::string text = gamma->string();
      if (text != "srgb" && closestMatch(text, {"srgb"}).empty()) gamma->failExpected(expectation);
      if (text != "srgb")
        gamma->fail("expected " + expectation + ", got " + describeJson(gamma->json()) +
                    ", did you mean \"srgb\"?");
      output.curve = GammaCurve::Srgb;
    } else {
      output.curve = GammaCurve::Power;
      output.gamma = gamma->number(expectation);
      if (!(output.gamma > 0)) gamma->failExpected(expectation);
    }
  }
  if (std::optional<JsonValue> exposure = fields.get("exposure"))
    output.exposure = exposure->number();
  if (std::optional<JsonValue> toneMap = fields.get("tone_map"))
    output.toneMap = ToneMap(toneMap->choice({"clamp", "reinhard", "aces"}));
  fields.finish();
}

}  // namespace candela
