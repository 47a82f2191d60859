// Reading render settings; see render_reader.h.
#include "scene/read/render_reader.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/read/did_you_mean.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// The widest filter a scene may ask for, in pixels from the centre: beyond it a filter blurs the
// image rather than reconstructs it.
constexpr float kMaxFilterRadius = 16.0f;

// "filter": a name ("box", "tent" or "gaussian", each with its default width: the tent's radius
// 1 pixel, the Gaussian's standard deviation 0.5, as Mitsuba 3's defaults), or an object of the
// type and its width, {"type": "tent", "radius": r} or {"type": "gaussian", "stddev": s}.
PixelFilter readFilter(const JsonValue& value) {
  const std::vector<std::string> names = {filterName(FilterType::Box), filterName(FilterType::Tent),
                                          filterName(FilterType::Gaussian)};
  const float defaultWidth[] = {0.5f, 1.0f, 0.5f};
  PixelFilter filter;
  if (!value.json().is_object()) {
    filter.type = FilterType(value.choice(names));
    filter.width = defaultWidth[size_t(filter.type)];
    return filter;
  }
  JsonObject fields(value, {"type", "radius", "stddev"},
                    "a filter name or an object {\"type\": name, ...}");
  filter.type = FilterType(fields.require("type").choice(names));
  filter.width = defaultWidth[size_t(filter.type)];
  if (filter.type != FilterType::Tent) fields.reject("radius", "only a \"tent\" filter has one");
  if (filter.type != FilterType::Gaussian)
    fields.reject("stddev", "only a \"gaussian\" filter has one");
  const char* widthName = filterWidthName(filter.type);
  if (std::optional<JsonValue> width = widthName ? fields.get(widthName) : std::nullopt) {
    filter.width = width->positiveNumber();
    if (!(filterRadius(filter) <= kMaxFilterRadius))
      width->failExpected(filter.type == FilterType::Tent
                              ? "a radius of at most " + formatNumber(kMaxFilterRadius) + " pixels"
                              : "a standard deviation of at most " +
                                    formatNumber(kMaxFilterRadius / kGaussianCutoff) +
                                    " pixels (the filter reaches " + formatNumber(kGaussianCutoff) +
                                    " of them from the centre)");
  }
  fields.finish();
  return filter;
}

}  // namespace

void readRender(const JsonValue& value, RenderSettings& render, OutputDesc& output) {
  JsonObject fields(value, {"max_depth", "integrator", "light_paths", "light_path_depth",
                            "first_hit_light_samples", "antialiasing", "filter",
                            "smooth_terminator", "seed", "gamma", "exposure", "tone_map"});
  if (std::optional<JsonValue> depth = fields.get("max_depth"))
    render.maxDepth = static_cast<uint32_t>(depth->integer(1, UINT32_MAX, "a positive integer"));
  if (std::optional<JsonValue> integrator = fields.get("integrator"))
    render.integrator =
        integrator->choice({"path", "direct"}) == 0 ? IntegratorType::Path : IntegratorType::Direct;
  if (std::optional<JsonValue> lightPaths = fields.get("light_paths"))
    render.lightPaths = LightPaths(lightPaths->choice({"auto", "on", "off"}));
  if (std::optional<JsonValue> depth = fields.get("light_path_depth")) {
    const std::string expected = "\"auto\", \"all\" or a positive integer";
    const Json& json = depth->json();
    if (json.is_string() && (json == "auto" || json == "all")) {
      render.lightPathDepth = json == "auto" ? 0 : kEveryInteraction;
    } else {
      const uint64_t interaction = depth->integer(1, UINT64_MAX, expected);
      // Deeper than any path: every interaction.
      render.lightPathDepth = uint32_t(std::min<uint64_t>(interaction, kEveryInteraction));
    }
  }
  if (std::optional<JsonValue> samples = fields.get("first_hit_light_samples")) {
    const std::string expected =
        "\"auto\" or an integer from 1 to " + std::to_string(kMaxFirstHitLightSamples);
    if (samples->json().is_string() && samples->string() == "auto") {
      render.firstHitLightSamples = 0;
    } else {
      // Checked against the top here, so that a count too large names the same range.
      const uint64_t count = samples->integer(1, UINT64_MAX, expected);
      if (count > kMaxFirstHitLightSamples) samples->failExpected(expected);
      render.firstHitLightSamples = uint32_t(count);
    }
  }
  if (std::optional<JsonValue> antialiasing = fields.get("antialiasing"))
    render.antialiasing = antialiasing->boolean();
  if (std::optional<JsonValue> filter = fields.get("filter")) {
    if (!render.antialiasing)
      filter->fail(
          "not used with \"antialiasing\": false (every sample goes through the pixel "
          "centre)");
    render.filter = readFilter(*filter);
  }
  if (std::optional<JsonValue> smooth = fields.get("smooth_terminator"))
    render.smoothTerminator = smooth->boolean();
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
