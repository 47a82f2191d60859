// Reading textures; see texture_reader.h.
#include "scene/read/texture_reader.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/constants.h"
#include "core/texture.h"
#include "image/image_io.h"
#include "scene/blackbody.h"
#include "scene/content_hash.h"
#include "scene/read/ies_profile.h"
#include "scene/read/resolve_path.h"
#include "scene/read/texel_check.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// Texture offsets are 32-bit element indices: a texture may hold at most 2^28 texels.
constexpr uint64_t kMaxTexels = uint64_t(1) << 28;

// An 8- or 16-bit image as a texture: colour from sRGB where it is read for colour, else (and its
// alpha always) linear.
void fromRgba(ImageRgba image, TextureUse use, TextureDesc* t, bool* hasAlpha) {
  t->width = image.width;
  t->height = image.height;
  *hasAlpha = image.channels == 2 || image.channels == 4;
  if (image.bits == 8) {
    t->format = use == TextureUse::Color ? TextureFormat::Srgb8 : TextureFormat::Linear8;
    t->texels8 = std::move(image.pixels8);
    return;
  }
  // A 16-bit PNG keeps its precision as floats, decoded as an 8-bit file would be: colour from
  // sRGB, masks and alpha linear.
  t->format = TextureFormat::Float;
  std::vector<float> linear(65536), decoded(65536);  // by 16-bit value, as the 8-bit table
  for (uint32_t v = 0; v < 65536; ++v) {
    linear[v] = float(v) * (1.0f / 65535.0f);
    decoded[v] = srgbToLinearValue(linear[v]);
  }
  const std::vector<float>& colour = use == TextureUse::Color ? decoded : linear;
  t->texelsF.resize(image.pixels16.size());
  for (size_t i = 0; i < image.pixels16.size(); ++i)
    t->texelsF[i] = (i % 4 == 3 ? linear : colour)[image.pixels16[i]];
}

TextureDesc decode(const std::string& path, TextureUse use, bool* hasAlpha) {
  TextureDesc t;
  t.file = path;
  requireTextureImagePath(path);
  if (isFloatImagePath(path)) {
    const ImageRGB image = readImage(path);
    const std::string bad = firstBadTexel(image);
    if (!bad.empty())
      throw SceneError(bad + "; expected finite, non-negative values in every texel");
    t.format = TextureFormat::Float;
    t.width = image.width;
    t.height = image.height;
    t.texelsF.reserve(size_t(4) * image.width * image.height);
    for (size_t i = 0; i + 2 < image.pixels.size(); i += 3)
      t.texelsF.insert(t.texelsF.end(),
                       {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2], 1.0f});
    *hasAlpha = false;
  } else {
    fromRgba(readImageRgba(path), use, &t, hasAlpha);
  }
  return t;
}

}  // namespace

LoadedTexture TextureLoader::load(const std::string& path, TextureUse use) {
  std::error_code error;
  std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  return add(error ? path : canonical.string(), use, [&](bool* hasAlpha) {
    try {
      return decode(path, use, hasAlpha);
    } catch (const SceneError&) {
      throw;
    } catch (const std::exception& e) {
      throw SceneError(std::string("cannot read the texture: ") + e.what());
    }
  });
}

LoadedTexture TextureLoader::loadEncoded(const std::string& bytes, const std::string& name,
                                         TextureUse use) {
  return add(name, use, [&](bool* hasAlpha) {
    TextureDesc texture;
    texture.file = name;
    try {
      fromRgba(decodeImageRgbaBytes(bytes, name), use, &texture, hasAlpha);
    } catch (const std::exception& e) {
      throw SceneError(std::string("cannot read the texture: ") + e.what());
    }
    return texture;
  });
}

LoadedTexture TextureLoader::add(const std::string& key, TextureUse use,
                                 const std::function<TextureDesc(bool* hasAlpha)>& make) {
  const auto found = loaded_.find({key, use});
  if (found != loaded_.end()) return found->second;
  LoadedTexture result;
  TextureDesc texture = make(&result.hasAlpha);
  if (texture.width == 0 || texture.height == 0)
    throw SceneError(texture.file + ": the texture is empty");
  if (uint64_t(texture.width) * texture.height > kMaxTexels)
    throw SceneError(texture.file + ": the texture has more than 2^28 texels");
  texture.contentHash = hashTexture(texture);
  result.index = int32_t(textures_.size());
  textures_.push_back(std::make_shared<const TextureDesc>(std::move(texture)));
  loaded_.emplace(std::make_pair(key, use), result);
  return result;
}

float texelValue(const TextureDesc& t, size_t i, uint32_t c) {
  if (t.format == TextureFormat::Float) return t.texelsF[4 * i + c];
  const float v = float(t.texels8[4 * i + c]) / 255.0f;
  return t.format == TextureFormat::Srgb8 && c < 3 ? srgbToLinearValue(v) : v;
}

std::string TextureLoader::resolve(const std::string& written) const {
  return resolvePath(written, baseDir_);
}

TextureLoader::LoadedProfile TextureLoader::loadProfile(const std::string& path,
                                                        const std::string& written) {
  std::error_code error;
  std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  const std::string key = error ? path : canonical.string();
  const auto found = profiles_.find(key);
  if (found != profiles_.end()) return found->second;
  const IesProfile profile = readIesProfile(path, written);
  LoadedProfile result;
  result.index = int32_t(textures_.size());
  result.first = profile.vertical.front();
  result.last = profile.vertical.back();
  textures_.push_back(std::make_shared<const TextureDesc>(profileTexture(profile, path)));
  profiles_.emplace(key, result);
  return result;
}

namespace {

// The keys a texture object may have beside "texture", "scale", "offset" and "rotation".
enum TextureKeys : unsigned { kNoMoreKeys = 0, kHeightKey = 1, kChannelKey = 2 };

// What a texture object gives: the texture, and the keys it was allowed to have.
struct TextureObject {
  TextureRef ref;
  float height = 1.0f;              // "height" (bump maps): a texel of value 1's, in scene units
  std::optional<uint32_t> channel;  // "channel" (scalar textures) where given: core/texture.h's
  bool hasAlpha = false;            // whether the image has an alpha channel
};

// A texture object's "checkerboard": [colour0, colour1] (each a number or [r, g, b], linear), as
// the 2 x 2 texture whose squares Mitsuba 3's `checkerboard` gives uv [0, 1)^2: colour0 where u
// and v are both past one half or neither is (the bottom-left and top-right squares).
int32_t readCheckerboard(const JsonValue& value, TextureLoader& textures, TextureUse use) {
  if (!value.json().is_array() || value.json().size() != 2)
    value.failExpected("an array of two colours, [colour0, colour1]");
  const std::vector<JsonValue> e = value.elements();
  const Vec3 c0 = e[0].colour(), c1 = e[1].colour();
  char key[160];
  std::snprintf(key, sizeof key, "checkerboard [%.9g %.9g %.9g] [%.9g %.9g %.9g]", c0.x, c0.y, c0.z,
                c1.x, c1.y, c1.z);
  return textures
      .add(key, use,
           [&](bool* hasAlpha) {
             TextureDesc t;
             t.file = key;
             t.format = TextureFormat::Float;
             t.width = t.height = 2;
             for (const Vec3& c : {c1, c0, c0, c1})
               t.texelsF.insert(t.texelsF.end(), {c.x, c.y, c.z, 1.0f});
             *hasAlpha = false;
             return t;
           })
      .index;
}

// A texture object {"texture": file, "scale": [su, sv], "offset": [ou, ov], "rotation": degrees,
// "wrap": mode or [mode, mode], "filter": "bilinear" or "nearest", ...}, its file read for `use`,
// with the further keys that `keys` allows.
TextureObject readTextureObject(const JsonValue& value, TextureLoader& textures, TextureUse use,
                                const std::string& expected, unsigned keys = kNoMoreKeys) {
  std::vector<std::string> known = {"texture",  "checkerboard", "scale", "offset",
                                    "rotation", "wrap",         "filter"};
  if (keys & kHeightKey) known.push_back("height");
  if (keys & kChannelKey) known.push_back("channel");
  JsonObject fields(value, std::move(known), expected);
  fields.exclusive("texture", "checkerboard");
  const std::optional<JsonValue> checkerboard = fields.get("checkerboard");
  if (!checkerboard && !fields.has("texture"))
    fields.fail(
        "missing required key \"texture\" (an image file) or \"checkerboard\" ([colour, colour])");
  TextureObject object;
  TextureRef& ref = object.ref;
  // A checkerboard's squares are its texels: read by the nearest texel, but where a bump map's
  // slopes need the bilinear lookup.
  if (checkerboard && !(keys & kHeightKey)) ref.filter = TextureFilter::Nearest;
  if (std::optional<JsonValue> scale = fields.get("scale")) {
    const std::string expectation = "an array of 2 finite, non-zero numbers";
    if (!scale->json().is_array() || scale->json().size() != 2) scale->failExpected(expectation);
    const std::vector<JsonValue> e = scale->elements();
    ref.scaleU = e[0].number("a finite, non-zero number");
    ref.scaleV = e[1].number("a finite, non-zero number");
    if (ref.scaleU == 0) e[0].failExpected("a finite, non-zero number");
    if (ref.scaleV == 0) e[1].failExpected("a finite, non-zero number");
  }
  if (std::optional<JsonValue> offset = fields.get("offset")) {
    if (!offset->json().is_array() || offset->json().size() != 2)
      offset->failExpected("an array of 2 finite numbers");
    const std::vector<JsonValue> e = offset->elements();
    ref.offsetU = e[0].number("a finite number");
    ref.offsetV = e[1].number("a finite number");
  }
  if (std::optional<JsonValue> rotation = fields.get("rotation")) {
    const double radians =
        std::fmod(double(rotation->number("an angle in degrees")), 360.0) * (kPiDouble / 180.0);
    ref.rotationCos = float(std::cos(radians));
    ref.rotationSin = float(std::sin(radians));
  }
  if (std::optional<JsonValue> wrap = fields.get("wrap")) {
    // In the order of TextureWrap's values; one for both axes, or [along s, along t].
    const std::vector<std::string> modes = {"repeat", "clamp", "mirror"};
    if (wrap->json().is_array()) {
      if (wrap->json().size() != 2)
        wrap->failExpected("\"repeat\", \"clamp\" or \"mirror\", or an array of two of them");
      const std::vector<JsonValue> e = wrap->elements();
      ref.wrapS = TextureWrap(e[0].choice(modes));
      ref.wrapT = TextureWrap(e[1].choice(modes));
    } else {
      ref.wrapS = ref.wrapT = TextureWrap(wrap->choice(modes));
    }
  }
  if (std::optional<JsonValue> filter = fields.get("filter")) {
    ref.filter = TextureFilter(filter->choice({"bilinear", "nearest"}));
    // A bump map's slopes are those of its bilinear interpolation; the nearest texel's are 0.
    if ((keys & kHeightKey) && ref.filter == TextureFilter::Nearest)
      filter->failExpected("\"bilinear\" (a bump map of the nearest texels would be flat)");
  }
  if (std::optional<JsonValue> given = fields.get("height")) {
    object.height = given->number("a finite, non-zero number");
    if (object.height == 0.0f) given->failExpected("a finite, non-zero number");
  }
  // In the order of core/texture.h's channel numbers.
  if (std::optional<JsonValue> given = fields.get("channel"))
    object.channel = uint32_t(given->choice({"r", "g", "b", "a", "luminance"}));
  const std::optional<JsonValue> file = fields.get("texture");
  fields.finish();
  if (checkerboard) {
    ref.index = readCheckerboard(*checkerboard, textures, use);
    return object;
  }
  const std::string written = file->string();
  if (written.empty()) file->failExpected("the path of an image file");
  try {
    const LoadedTexture loaded = textures.load(textures.resolve(written), use);
    ref.index = loaded.index;
    object.hasAlpha = loaded.hasAlpha;
  } catch (const SceneError& e) {
    file->fail(e.what());
  }
  return object;
}

}  // namespace

Vec3 readTexturedColour(const JsonValue& value, TextureLoader& textures, TextureRef* texture) {
  if (!value.json().is_object()) return value.colour();
  *texture =
      readTextureObject(value, textures, TextureUse::Color, "a colour or a texture object").ref;
  return Vec3(1.0f);
}

Vec3 readLightColour(const JsonValue& value, TextureLoader& textures, TextureRef* texture) {
  if (!value.json().is_object() || !value.json().contains("temperature"))
    return readTexturedColour(value, textures, texture);
  JsonObject fields(value, {"temperature"});
  const JsonValue temperature = fields.require("temperature");
  const double kelvin = temperature.number();
  if (!(kelvin >= kBlackbodyMinKelvin && kelvin <= kBlackbodyMaxKelvin))
    temperature.failExpected("a temperature in kelvin from " + formatNumber(kBlackbodyMinKelvin) +
                             " to " + formatNumber(kBlackbodyMaxKelvin));
  fields.finish();
  return blackbodyColour(kelvin);
}

TextureRef readNormalMap(const JsonValue& value, TextureLoader& textures) {
  if (!value.json().is_object())
    value.failExpected("a texture object {\"texture\": file, \"scale\": [su, sv]}");
  return readTextureObject(value, textures, TextureUse::Linear, "a texture object").ref;
}

TextureRef readBumpMap(const JsonValue& value, TextureLoader& textures, float* height) {
  const std::string expected =
      "a texture object {\"texture\": file, \"scale\": [su, sv], \"height\": h}";
  if (!value.json().is_object()) value.failExpected(expected);
  const TextureObject map =
      readTextureObject(value, textures, TextureUse::Linear, expected, kHeightKey);
  *height = map.height;
  return map.ref;
}

TextureRef readUnitTexture(const JsonValue& value, TextureLoader& textures,
                           const std::string& expected, uint32_t* channel) {
  const TextureObject map =
      readTextureObject(value, textures, TextureUse::Linear, expected, kChannelKey);
  *channel = map.channel.value_or(kLuminanceChannel);
  return map.ref;
}

AlphaMask readAlpha(const JsonValue& value, TextureLoader& textures) {
  AlphaMask mask;
  if (!value.json().is_object()) {
    mask.constant = value.unitNumber("an alpha in [0, 1]", " or a texture object");
    return mask;
  }
  const TextureObject map = readTextureObject(
      value, textures, TextureUse::Linear, "an alpha in [0, 1] or a texture object", kChannelKey);
  mask.texture = map.ref;
  mask.channel = map.channel.value_or(map.hasAlpha ? 3u : kLuminanceChannel);
  return mask;
}

}  // namespace candela
