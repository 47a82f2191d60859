// Reading materials; see material_reader.h.
#include "scene/read/material_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "render/material_prepare.h"
#include "scene/cauchy_index.h"
#include "scene/read/did_you_mean.h"
#include "scene/read/json_parse.h"
#include "scene/read/metal_table.h"
#include "scene/read/texel_check.h"
#include "scene/read/text_file.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

const std::vector<std::string> kTypeNames = {"diffuse",   "mirror",  "glass",      "emissive",
                                             "conductor", "plastic", "thin_glass", "mix"};
// The types the seed shorthand may name: the first three.
constexpr size_t kShorthandCount = 3;
enum TypeIndex : size_t {
  kDiffuse,
  kMirror,
  kGlass,
  kEmissive,
  kConductor,
  kPlastic,
  kThinGlass,
  kMix
};

// Every field a material may have, and which of them each type reads.
// clang-format off
const std::vector<std::string> kFields = {
    "color", "ior", "roughness", "metal", "radiance", "strength", "two_sided", "normal_map",
    "bump_map", "alpha", "emission", "emission_strength", "emission_two_sided",
    "transmission_depth", "abbe", "visible", "anisotropy", "anisotropy_rotation", "materials",
    "weight", "coat", "coat_roughness", "coat_ior", "coat_normal_map", "sheen", "sheen_roughness",
    "transmittance", "scattering", "scattering_anisotropy"};
const std::vector<std::vector<std::string>> kFieldsOf = {
    {"color", "normal_map", "bump_map", "alpha", "emission", "emission_strength", "emission_two_sided",
     "coat", "coat_roughness", "coat_ior", "coat_normal_map", "sheen",
     "sheen_roughness", "transmittance"},  // diffuse
    {"color", "normal_map", "bump_map", "alpha", "emission", "emission_strength", "emission_two_sided",
     "coat", "coat_roughness", "coat_ior", "coat_normal_map", "sheen",
     "sheen_roughness"},  // mirror
    {"color", "ior", "roughness", "anisotropy", "anisotropy_rotation", "normal_map", "bump_map",
     "alpha", "emission", "emission_strength", "transmission_depth", "abbe", "scattering",
     "scattering_anisotropy"},  // glass
    {"radiance", "strength", "two_sided", "visible"},                          // emissive
    {"color", "roughness", "anisotropy", "anisotropy_rotation", "metal", "normal_map", "bump_map",
     "alpha", "emission", "emission_strength", "emission_two_sided", "coat", "coat_roughness",
     "coat_ior", "coat_normal_map", "sheen", "sheen_roughness"},  // conductor
    {"color", "ior", "roughness", "normal_map", "bump_map", "alpha", "emission",
     "emission_strength", "emission_two_sided", "coat", "coat_roughness", "coat_ior",
     "coat_normal_map", "sheen", "sheen_roughness"},  // plastic
    {"ior"},  // thin_glass
    {"materials", "weight", "alpha", "emission", "emission_strength", "emission_two_sided"},  // mix
};
// clang-format on

// The material a mix names for a part: one of the library's, or a shorthand type's defaults.
using NamedMaterial = std::function<MaterialRead(const JsonValue& name)>;

// Why `field` is refused on a material of type kTypeNames[type].
std::string notUsedBy(size_t type, const std::string& field) {
  const std::string why = std::string("not used by ") + (type == kEmissive ? "an " : "a ") +
                          quoted(kTypeNames[type]) + " material";
  if (type == kEmissive && field.rfind("emission", 0) == 0)
    return why + " (it emits its \"radiance\" times its \"strength\")";
  if (field == "transmittance")
    return why + " (a \"diffuse\" one lets light through diffusely" +
           (type == kGlass ? std::string("; a glass's \"color\" tints what passes it)") : ")");
  if (field.rfind("scattering", 0) == 0)
    return why + " (a \"glass\" holds a scattering medium inside)";
  return why;
}

// A roughness field's value: a number into *number, or a texture object into *texture and its
// channel into *channel.
void readRoughnessValue(const JsonValue& value, TextureLoader& textures, float* number,
                        TextureRef* texture, uint32_t* channel) {
  if (value.json().is_object())
    *texture =
        readUnitTexture(value, textures, "a roughness in [0, 1] or a texture object", channel);
  else
    *number = value.unitNumber("a roughness in [0, 1]", " or a texture object");
}

// "roughness" into material->roughness, or its texture into material->roughnessTexture.
void readRoughness(JsonObject& fields, TextureLoader& textures, Material* material) {
  if (const std::optional<JsonValue> value = fields.get("roughness"))
    readRoughnessValue(*value, textures, &material->roughness, &material->roughnessTexture,
                       &material->roughnessChannel);
}

// "anisotropy" a in [0, 1] and "anisotropy_rotation" (degrees) into the material: the roughness
// along the surface's tangent and across it (render/microfacet.h, tangentAlpha).
void readAnisotropy(JsonObject& fields, Material* material) {
  if (std::optional<JsonValue> value = fields.get("anisotropy"))
    material->anisotropy = value->unitNumber("an anisotropy in [0, 1]");
  if (std::optional<JsonValue> rotation = fields.get("anisotropy_rotation")) {
    const float degrees = rotation->number("an angle in degrees");
    if (material->anisotropy == 0.0f)
      rotation->fail(
          "turns the tangent of an anisotropic material; expected an \"anisotropy\" "
          "above 0 beside it");
    material->anisotropyRotation = float(std::fmod(double(degrees), 360.0) * kPi / 180.0);
  }
}

// "coat", the share of the surface a clear coat covers (a number, or a texture object of them),
// and that coat's "coat_roughness" (a number or a texture object), "coat_ior" and
// "coat_normal_map" (render/bsdf_coat.h).
void readCoat(JsonObject& fields, TextureLoader& textures, Material* material) {
  const std::optional<JsonValue> coat = fields.get("coat");
  if (coat && coat->json().is_object()) {
    material->coatTexture = readUnitTexture(
        *coat, textures, "a coat weight in [0, 1] or a texture object", &material->coatChannel);
    material->coatWeight = 1.0f;  // the texture's values are the weight
  } else if (coat) {
    material->coatWeight = coat->unitNumber("a coat weight in [0, 1]", " or a texture object");
  }
  const std::optional<JsonValue> roughness = fields.get("coat_roughness");
  const std::optional<JsonValue> ior = fields.get("coat_ior");
  const std::optional<JsonValue> normalMap = fields.get("coat_normal_map");
  for (const std::optional<JsonValue>* field : {&roughness, &ior, &normalMap})
    if (*field && !coat)
      (*field)->fail("describes a clear coat; expected a \"coat\" (its weight) beside it");
  if (roughness)
    readRoughnessValue(*roughness, textures, &material->coatRoughness,
                       &material->coatRoughnessTexture, &material->coatRoughnessChannel);
  if (ior) material->coatIor = ior->positiveNumber();
  if (normalMap) material->coatNormalMap = readNormalMap(*normalMap, textures);
}

// "sheen", the colour of a sheen over the material (each channel in [0, 1]; or a texture object,
// as a "color" may be), and its "sheen_roughness" (a number or a texture object;
// render/bsdf_sheen.h).
void readSheen(JsonObject& fields, TextureLoader& textures, Material* material) {
  const std::optional<JsonValue> sheen = fields.get("sheen");
  const std::optional<JsonValue> roughness = fields.get("sheen_roughness");
  if (roughness && !sheen)
    roughness->fail("describes a sheen; expected a \"sheen\" (its colour) beside it");
  if (!sheen) return;
  material->sheenColor = readTexturedColour(*sheen, textures, &material->sheenTexture);
  if (maxComponent(material->sheenColor) > 1.0f)
    sheen->fail("expected a colour of channels in [0, 1], got " + formatVec3(material->sheenColor));
  if (roughness)
    readRoughnessValue(*roughness, textures, &material->sheenRoughness,
                       &material->sheenRoughnessTexture, &material->sheenRoughnessChannel);
}

// A diffuse material's "transmittance": the share of light, by colour, that it lets through
// diffusely (each channel in [0, 1]; or a texture object, as a "color" may be); a translucent sheet
// takes no coat or sheen, whose layers cover one side.
void readTransmittance(const JsonValue& value, JsonObject& fields, TextureLoader& textures,
                       Material* material) {
  material->transmittance = readTexturedColour(value, textures, &material->transmittanceTexture);
  if (maxComponent(material->transmittance) > 1.0f)
    value.fail("expected a colour of channels in [0, 1], got " +
               formatVec3(material->transmittance));
  if (isBlack(material->transmittance) && material->transmittanceTexture.index < 0) return;
  material->type = MaterialType::Translucent;
  if (fields.has("coat") || fields.has("sheen"))
    value.fail("a translucent material takes no \"coat\" or \"sheen\" (they lie on one side)");
}

// `radiance` (a colour, or a texture: material->emissionTexture) times the field `strengthKey`
// (default 1) into material->radiance.
void readRadiance(JsonObject& fields, const JsonValue& radiance, const std::string& strengthKey,
                  TextureLoader& textures, Material* material) {
  material->radiance = readLightColour(radiance, textures, &material->emissionTexture);
  if (std::optional<JsonValue> strength = fields.get(strengthKey)) {
    const float k = strength->nonNegativeNumber();
    const Vec3 scaled = material->radiance * k;
    if (!isFinite(scaled))
      strength->fail("the radiance " + formatVec3(material->radiance) + " times " + strengthKey +
                     " " + formatNumber(k) + " is beyond single precision; expected a smaller " +
                     strengthKey);
    if (material->emissionTexture.index >= 0) {  // its tint is 1: the texels times k
      const std::string beyond =
          firstTexelBeyondFloat(textures.texture(material->emissionTexture.index), scaled);
      if (!beyond.empty())
        strength->fail("the radiance texture's " + beyond + " times " + strengthKey + " " +
                       formatNumber(k) + " is beyond single precision; expected a smaller " +
                       strengthKey);
    }
    material->radiance = scaled;
  }
}

// An emissive material's "radiance" times its "strength", "two_sided" and "visible".
void readEmissive(JsonObject& fields, TextureLoader& textures, Material* material) {
  material->type = MaterialType::Emissive;
  readRadiance(fields, fields.require("radiance"), "strength", textures, material);
  if (std::optional<JsonValue> twoSided = fields.get("two_sided"))
    material->twoSided = twoSided->boolean();
  if (std::optional<JsonValue> visible = fields.get("visible"))
    material->hiddenFromCamera = !visible->boolean();
}

// The "emission" of a material that reflects (or transmits) as well, times its
// "emission_strength": it emits as an emissive material of that radiance would, from its front
// side (from both where "emission_two_sided", but on glass, whose back is its inside), and is a
// light. An emitting surface is sampled over all its area, so it has no alpha.
void readSurfaceEmission(JsonObject& fields, TextureLoader& textures, Material* material) {
  const std::optional<JsonValue> emission = fields.get("emission");
  if (!emission) {
    fields.reject("emission_strength", "not used without an \"emission\" beside it");
    fields.reject("emission_two_sided", "not used without an \"emission\" beside it");
    return;
  }
  readRadiance(fields, *emission, "emission_strength", textures, material);
  if (std::optional<JsonValue> twoSided = fields.get("emission_two_sided"))
    material->twoSided = twoSided->boolean();
  if (isMasked(material->alpha) && hasEmission(*material))
    emission->fail(
        "makes a light of a surface with an \"alpha\", which lights sample over all their "
        "area; expected no \"alpha\" on an emitting material");
}

// Glass's "transmission_depth" d: its `color` c is then what white light keeps of each channel
// after d units inside, absorbed by Beer's law at the coefficient -ln(c) / d, and no longer a
// tint at each crossing (OpenPBR's and Autodesk Standard Surface's transmission_depth).
void readAbsorption(const JsonValue& depth, const std::optional<JsonValue>& color,
                    Material* material) {
  const float d = depth.positiveNumber();
  const Vec3 kept = material->color;
  for (int c = 0; c < 3; ++c)
    if (!(kept[c] > 0.0f && kept[c] <= 1.0f))
      color->failExpected(
          "a colour in (0, 1] in every channel with \"transmission_depth\" "
          "(what white light keeps after that depth inside)");
  for (int c = 0; c < 3; ++c) material->absorption[c] = -std::log(kept[c]) / d;
  if (!isFinite(material->absorption))
    color->fail("absorbs more over " + formatNumber(d) +
                " than single precision can say; expected a longer transmission_depth or a "
                "lighter colour");
  material->color = Vec3(1.0f);
}

// Glass's "scattering": the scattering coefficient of its inside, per unit length (a grey number or
// [r, g, b]), and the "scattering_anisotropy" g of its Henyey-Greenstein phase function.
void readScattering(JsonObject& fields, Material* material) {
  const std::optional<JsonValue> scattering = fields.get("scattering");
  if (!scattering) {
    fields.reject("scattering_anisotropy", "not used without a \"scattering\" beside it");
    return;
  }
  material->scattering = scattering->colour();
  if (std::optional<JsonValue> g = fields.get("scattering_anisotropy")) {
    const float value = g->number();
    if (!(value > -1.0f && value < 1.0f))
      g->failExpected("a number between -1 and 1, exclusive (0 scatters alike in every direction)");
    material->scatteringAnisotropy = value;
  }
}

// Glass's "abbe": its Abbe number, which with its ior (at the d line) gives its index in each
// colour channel (scene/cauchy_index.h).
void readDispersion(const JsonValue& abbe, Material* material) {
  const float v = abbe.positiveNumber();
  // Below an Abbe number of 1 Cauchy's law bends blue light past sense (its index can fall
  // below 1); real glasses lie between about 15 and 100.
  if (!(v >= 1.0f)) abbe.failExpected("an Abbe number of at least 1 (glasses have 15 to 100)");
  if (!(material->ior > 1.0f))
    abbe.fail("needs an \"ior\" above 1 (a glass denser than what surrounds it), got " +
              formatNumber(material->ior));
  for (int c = 0; c < 3; ++c)
    material->channelIor[c] = float(cauchyIndex(material->ior, v, kChannelLambda[c]));
}

void readMetal(const JsonValue& value, Material* material) {
  std::vector<std::string> names;
  for (const NamedMetal& metal : namedMetals()) names.push_back(metal.name);
  const NamedMetal& metal = namedMetals()[value.choice(names)];
  material->metal = true;
  material->metalEta = metal.eta;
  material->metalK = metal.k;
}

MaterialRead readMaterialObject(const JsonValue& value, TextureLoader& textures,
                                const NamedMaterial& named);

// A part of a mix may be any material that reflects or transmits: what emits is a light of its
// own, and what lets rays through (alpha, thin glass) does so for the whole surface.
void checkMixPart(const JsonValue& where, const Material& part) {
  if (part.type == MaterialType::Emissive)
    where.fail(
        "an emissive material in a mix; expected a material that reflects or transmits (an "
        "emitting surface is an \"emissive\" material of its own)");
  if (hasEmission(part))
    where.fail(
        "a material with an \"emission\" in a mix; expected the \"emission\" on the mix, "
        "which emits from the whole surface");
  if (part.alpha.thinSheetIor > 0.0f)
    where.fail("a \"thin_glass\" material in a mix; expected it on a surface of its own");
  if (isMasked(part.alpha))
    where.fail(
        "a material with an \"alpha\" in a mix; expected the \"alpha\" on the mix, which "
        "masks the whole surface");
}

// Appends `part` and its own parts to `parts`, its mixes' indices moved to where they land;
// returns the index of the part.
uint32_t appendPart(std::vector<Material>* parts, const MaterialRead& part) {
  const uint32_t index = uint32_t(parts->size());
  parts->push_back(part.material);
  parts->insert(parts->end(), part.parts.begin(), part.parts.end());
  for (size_t i = index; i < parts->size(); ++i)
    if ((*parts)[i].type == MaterialType::Mix)
      for (uint32_t& p : (*parts)[i].mixParts) p += index + 1;
  return index;
}

// A mix's "materials", two names or material objects, and its "weight", the share of the second:
// a number in [0, 1] or a texture object of them.
MaterialRead readMix(JsonObject& fields, TextureLoader& textures, const NamedMaterial& named) {
  MaterialRead mix;
  mix.material.type = MaterialType::Mix;
  const JsonValue list = fields.require("materials");
  const std::string expected = "an array of two materials, each a name or a material object";
  if (!list.json().is_array() || list.json().size() != 2) list.failExpected(expected);
  const std::vector<JsonValue> elements = list.elements();
  for (size_t i = 0; i < 2; ++i) {
    const JsonValue& element = elements[i];
    MaterialRead part;
    if (element.json().is_object())
      part = readMaterialObject(element, textures, named);
    else if (element.json().is_string())
      part = named(element);
    else
      element.failExpected("a material name or a material object");
    checkMixPart(element, part.material);
    mix.material.mixParts[i] = appendPart(&mix.parts, part);
  }
  if (std::optional<JsonValue> weight = fields.get("weight")) {
    const std::string orElse = " or a texture object";
    if (weight->json().is_object())
      mix.material.mixWeightTexture = readUnitTexture(
          *weight, textures, "a weight in [0, 1]" + orElse, &mix.material.mixWeightChannel);
    else
      mix.material.mixWeight = weight->unitNumber("a weight in [0, 1]", orElse);
  }
  if (std::optional<JsonValue> alpha = fields.get("alpha"))
    mix.material.alpha = readAlpha(*alpha, textures);
  readSurfaceEmission(fields, textures, &mix.material);
  return mix;
}

// The fields of a material of type kTypeNames[type], read from `fields`: the material object
// itself, or for the shorthand the sphere or object that carries them.
MaterialRead readFields(JsonObject& fields, size_t type, TextureLoader& textures,
                        const NamedMaterial& named) {
  for (const std::string& field : kFields) {
    const std::vector<std::string>& used = kFieldsOf[type];
    if (std::find(used.begin(), used.end(), field) == used.end())
      fields.reject(field, notUsedBy(type, field));
  }
  if (type == kMix) return readMix(fields, textures, named);
  Material material;
  if (type == kEmissive) {
    readEmissive(fields, textures, &material);
    return {material, {}};
  }
  const float defaultColor[] = {0.8f, 1.0f, 1.0f, 0.0f, 1.0f, 0.5f, 1.0f, 0.0f};
  const std::optional<JsonValue> color = fields.get("color");
  // Glass alone takes no texture: its colour tints what passes through, not a surface.
  if (color && type != kGlass)
    material.color = readTexturedColour(*color, textures, &material.colorTexture);
  else
    material.color = color ? color->colour() : Vec3(defaultColor[type]);
  const std::optional<JsonValue> normalMap = fields.get("normal_map");
  const std::optional<JsonValue> bumpMap = fields.get("bump_map");
  if (normalMap && bumpMap)
    fields.fail("give a material a \"normal_map\" or a \"bump_map\", not both");
  if (normalMap) material.normalMap = readNormalMap(*normalMap, textures);
  if (bumpMap) material.normalMap = readBumpMap(*bumpMap, textures, &material.bumpHeight);
  if (std::optional<JsonValue> alpha = fields.get("alpha"))
    material.alpha = readAlpha(*alpha, textures);
  switch (type) {
    case kDiffuse:
      material.type = MaterialType::Diffuse;
      if (std::optional<JsonValue> transmittance = fields.get("transmittance"))
        readTransmittance(*transmittance, fields, textures, &material);
      break;
    case kMirror:
      material.type = MaterialType::Conductor;
      break;
    case kConductor:
      material.type = MaterialType::Conductor;
      readRoughness(fields, textures, &material);
      readAnisotropy(fields, &material);
      if (std::optional<JsonValue> metal = fields.get("metal")) {
        if (color) fields.fail("give a conductor either \"color\" or \"metal\", not both");
        readMetal(*metal, &material);
      }
      break;
    case kGlass:
    case kPlastic:
      material.type = type == kGlass ? MaterialType::Glass : MaterialType::Plastic;
      readRoughness(fields, textures, &material);
      if (type == kGlass) readAnisotropy(fields, &material);
      if (std::optional<JsonValue> ior = fields.get("ior")) material.ior = ior->positiveNumber();
      if (std::optional<JsonValue> depth = fields.get("transmission_depth"))
        readAbsorption(*depth, color, &material);
      if (std::optional<JsonValue> abbe = fields.get("abbe")) readDispersion(*abbe, &material);
      if (type == kGlass) readScattering(fields, &material);
      break;
    case kThinGlass:
      // What the sheet transmits passes the alpha test (geometry/alpha_mask.h); a face that
      // stays reflects all that reaches it, as a white mirror.
      material.type = MaterialType::Conductor;
      if (std::optional<JsonValue> ior = fields.get("ior")) material.ior = ior->positiveNumber();
      material.alpha.thinSheetIor = material.ior;
      break;
  }
  if (type != kThinGlass) readSurfaceEmission(fields, textures, &material);
  readCoat(fields, textures, &material);
  readSheen(fields, textures, &material);
  prepareMaterial(&material);
  return {material, {}};
}

[[noreturn]] void failUnknownMaterial(const JsonValue& value, const std::string& name,
                                      const std::vector<std::string>& names) {
  std::vector<std::string> candidates(kTypeNames.begin(), kTypeNames.begin() + kShorthandCount);
  candidates.insert(candidates.end(), names.begin(), names.end());
  const std::string suggestion = closestMatch(name, candidates);
  if (!suggestion.empty())
    value.fail("unknown material " + quoted(name) + ", did you mean " + quoted(suggestion) + "?");
  std::string hint =
      "expected \"diffuse\", \"mirror\", \"glass\" or a name defined under "
      "\"materials\"";
  if (name == "emissive")
    hint +=
        "; an emissive material is written as an object: {\"type\": \"emissive\", "
        "\"radiance\": ...}";
  value.fail("unknown material " + quoted(name) + ", " + hint);
}

// A shorthand type's material with every field at its default, as a mix may name it.
MaterialRead shorthandMaterial(size_t type) {
  Material material;
  if (type != kDiffuse) {
    material.type = type == kMirror ? MaterialType::Conductor : MaterialType::Glass;
    material.color = Vec3(1.0f);
  }
  prepareMaterial(&material);
  return {material, {}};
}

MaterialRead readMaterialObject(const JsonValue& value, TextureLoader& textures,
                                const NamedMaterial& named) {
  std::vector<std::string> known = {"type"};
  known.insert(known.end(), kFields.begin(), kFields.end());
  JsonObject fields(value, known, "a material object");
  const size_t type = fields.require("type").choice(kTypeNames);
  MaterialRead material = readFields(fields, type, textures, named);
  fields.finish();
  return material;
}

// The names of a library's entries, for suggestions.
template <class Map>
std::vector<std::string> namesOf(const Map& map) {
  std::vector<std::string> names;
  for (const auto& entry : map) names.push_back(entry.first);
  return names;
}

// Reads the top-level "materials" in whatever order its mixes name each other.
class LibraryReader {
 public:
  explicit LibraryReader(TextureLoader& textures) : textures_(textures) {}

  // Adds the materials of `value` (name -> material), whose files lie relative to `folder`.
  void add(const JsonValue& value, const std::string& folder) {
    if (!value.json().is_object()) value.failExpected("an object (material name -> material)");
    for (const auto& item : value.json().items()) {
      if (isCommentKey(item.key())) continue;
      const JsonValue entry(item.value(), value.file(), memberPath(value.path(), item.key()));
      const auto [found, fresh] = entries_.emplace(item.key(), Entry{entry, folder});
      if (!fresh)
        entry.fail("the material " + quoted(item.key()) + " is defined twice, first at " +
                   found->second.value.file() + ": " + found->second.value.path());
    }
  }

  MaterialLibrary read() {
    for (const auto& entry : entries_) named(entry.first, entry.second.value);
    return std::move(library_);
  }

 private:
  struct Entry {
    JsonValue value;
    std::string folder;  // its textures' paths are relative to this
  };

  // The material named `name`, read on first use; `where` is what names it.
  const MaterialRead& named(const std::string& name, const JsonValue& where) {
    const auto done = library_.find(name);
    if (done != library_.end()) return done->second;
    if (!reading_.insert(name).second)
      where.fail("the mix " + quoted(name) +
                 " contains itself; expected parts that are other materials");
    const NamedMaterial lookup = [this](const JsonValue& part) {
      const std::string partName = part.string();
      if (entries_.count(partName)) return named(partName, part);
      for (size_t type = 0; type < kShorthandCount; ++type)
        if (partName == kTypeNames[type]) return shorthandMaterial(type);
      failUnknownMaterial(part, partName, namesOf(entries_));
    };
    const Entry& entry = entries_.at(name);
    const TextureLoader::BaseDirScope folder(textures_, entry.folder);
    MaterialRead material = readMaterialObject(entry.value, textures_, lookup);
    reading_.erase(name);
    return library_[name] = std::move(material);
  }

  TextureLoader& textures_;
  std::map<std::string, Entry> entries_;
  MaterialLibrary library_;
  std::set<std::string> reading_;  // the mixes being read, which a part may not name
};

}  // namespace

MaterialLibrary readMaterialLibrary(const JsonValue& value, TextureLoader& textures) {
  LibraryReader reader(textures);
  std::vector<std::unique_ptr<Json>> files;  // the library files' documents, alive while read
  const auto addOne = [&](const JsonValue& part) {
    if (part.json().is_object()) return reader.add(part, textures.baseDir());
    if (!part.json().is_string())
      part.failExpected(
          "an object (material name -> material), the path of a JSON file of "
          "them, or an array of those");
    const std::string written = part.string();
    if (written.empty()) part.failExpected("the path of a JSON file of materials");
    const std::string path = textures.resolve(written);
    std::string text, reason;
    if (!readTextFile(path, &text, &reason))
      part.fail("cannot open the material library " + written + " (" + reason + ")");
    files.push_back(std::make_unique<Json>(parseJson(text, path)));
    reader.add(JsonValue(*files.back(), path, ""),
               std::filesystem::path(path).parent_path().string());
  };
  if (value.json().is_array()) {
    for (const JsonValue& part : value.elements()) addOne(part);
  } else {
    addOne(value);
  }
  return reader.read();
}

std::optional<MaterialRead> readMaterialReference(JsonObject& owner, const MaterialLibrary& library,
                                                  TextureLoader& textures) {
  const NamedMaterial named = [&library](const JsonValue& part) {
    const std::string name = part.string();
    const auto found = library.find(name);
    if (found != library.end()) return found->second;
    for (size_t type = 0; type < kShorthandCount; ++type)
      if (name == kTypeNames[type]) return shorthandMaterial(type);
    failUnknownMaterial(part, name, namesOf(library));
  };
  const std::optional<JsonValue> reference = owner.get("material");
  if (!reference) {
    owner.reject("ior", "not used without a \"glass\" material");
    if (std::optional<JsonValue> color = owner.get("color")) {
      MaterialRead diffuse;
      diffuse.material.color = readTexturedColour(*color, textures, &diffuse.material.colorTexture);
      return diffuse;
    }
    return std::nullopt;
  }
  if (reference->json().is_object()) {
    const std::string reason = "not used beside an inline material (put it inside \"material\")";
    owner.reject("color", reason);
    owner.reject("ior", reason);
    return readMaterialObject(*reference, textures, named);
  }
  if (!reference->json().is_string())
    reference->failExpected("a material name or a material object");

  const std::string name = reference->string();
  // A named material wins over the shorthand of the same name: the scene's author defined it on
  // purpose, and a library entry called "glass" would otherwise be unreachable.
  const auto found = library.find(name);
  if (found != library.end()) {
    const std::string reason = "not used with the named material " + quoted(name);
    owner.reject("color", reason);
    owner.reject("ior", reason);
    return found->second;
  }
  for (size_t type = 0; type < kShorthandCount; ++type)
    if (name == kTypeNames[type]) return readFields(owner, type, textures, named);
  failUnknownMaterial(*reference, name, namesOf(library));
}

}  // namespace candela
