// glTF materials as candela's; see gltf_materials.h.
#include "scene/read/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/texture.h"
#include "image/image_io.h"
#include "render/material_prepare.h"
#include "scene/read/gltf_extension_values.h"
#include "scene/read/gltf_uri.h"
#include "scene/read/texel_check.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// The extensions of a material that candela reads; any other a material uses gets a warning.
const std::set<std::string> kReadExtensions = {"KHR_materials_emissive_strength",
                                               "KHR_materials_ior",
                                               "KHR_materials_transmission",
                                               "KHR_materials_volume",
                                               "KHR_materials_dispersion",
                                               "KHR_materials_clearcoat",
                                               "KHR_materials_sheen",
                                               "KHR_materials_specular",
                                               "KHR_materials_diffuse_transmission",
                                               "KHR_materials_unlit",
                                               "KHR_materials_anisotropy"};

Vec3 colourFactor(const std::vector<double>& values, const std::string& where) {
  if (values.size() < 3) throw SceneError(where + ": expected at least 3 numbers");
  const Vec3 colour{float(values[0]), float(values[1]), float(values[2])};
  for (int c = 0; c < 3; ++c)
    if (!(colour[c] >= 0.0f && std::isfinite(colour[c])))
      throw SceneError(where + ": expected finite, non-negative numbers, got " +
                       formatVec3(colour));
  return colour;
}

// s's material, its parts (and theirs) appended to *parts after it.
Material place(const Shading& s, std::vector<Material>* parts) {
  Material m = s.material;
  if (m.type != MaterialType::Mix) return m;
  for (int i = 0; i < 2; ++i) {
    m.mixParts[i] = uint32_t(parts->size());
    parts->emplace_back();
  }
  for (int i = 0; i < 2; ++i) (*parts)[m.mixParts[i]] = place(s.parts[size_t(i)], parts);
  return m;
}

}  // namespace

void GltfMaterialReader::warnOnce(const std::string& message) {
  if (warned_.insert(message).second) warnings_->push_back(label_ + ": " + message);
}

TextureRef GltfMaterialReader::texture(const TextureSlot& slot, TextureUse use,
                                       const std::string& where, bool* hasAlpha) {
  if (size_t(slot.index) >= model_.textures.size())
    throw SceneError(label_ + ": " + where + ".index: texture " + std::to_string(slot.index) +
                     " does not exist (" + std::to_string(model_.textures.size()) + " textures)");
  const tinygltf::Texture& t = model_.textures[size_t(slot.index)];
  const std::string textureWhere = "textures[" + std::to_string(slot.index) + "]";
  // EXT_texture_webp names a WebP image, read in place of the (fallback) source where this build
  // decodes WebP.
  int source = t.source;
  std::string sourceWhere = textureWhere + ".source";
  const auto webp = t.extensions.find("EXT_texture_webp");
  if (webp != t.extensions.end() && webpDecoding() && webp->second.Get("source").IsInt()) {
    source = webp->second.Get("source").GetNumberAsInt();
    sourceWhere = textureWhere + ".extensions.EXT_texture_webp.source";
  }
  if (source < 0 || size_t(source) >= model_.images.size())
    throw SceneError(label_ + ": " + sourceWhere + ": " +
                     (source < 0 ? std::string("no PNG, JPEG or WebP image (a KTX2 source, which "
                                               "candela does not read?)")
                                 : "image " + std::to_string(source) + " does not exist (" +
                                       std::to_string(model_.images.size()) + " images)"));
  const tinygltf::Image& image = model_.images[size_t(source)];
  const std::string imageWhere = label_ + ": images[" + std::to_string(source) + "]";
  LoadedTexture loaded;
  const auto bytes = embedded_.find(source);
  if (bytes != embedded_.end()) {
    const std::string name = label_ + " (images[" + std::to_string(source) + "]" +
                             (image.name.empty() ? "" : " \"" + image.name + "\"") + ")";
    try {
      loaded = textures_.loadEncoded(bytes->second, name, use);
    } catch (const SceneError& e) {
      throw SceneError(imageWhere + ": " + e.what());
    }
  } else if (!image.uri.empty()) {
    const std::string path = gltfUriPath(image.uri, folder_);
    try {
      loaded = textures_.load(path, use);
    } catch (const SceneError& e) {
      throw SceneError(imageWhere + ".uri: " + e.what());
    }
  } else {
    throw SceneError(imageWhere + ": expected a uri or a bufferView");
  }
  if (hasAlpha) *hasAlpha = loaded.hasAlpha;
  TextureRef ref;
  ref.index = loaded.index;
  if (t.sampler >= 0) {
    // glTF's wrapS and wrapT act in the image's coordinates, after KHR_texture_transform, as
    // candela's do; its magnification filter says whether texels are blended or kept whole (the
    // minification filter picks among mipmaps, which candela does not make).
    if (size_t(t.sampler) >= model_.samplers.size())
      throw SceneError(label_ + ": " + textureWhere + ".sampler: sampler " +
                       std::to_string(t.sampler) + " does not exist (" +
                       std::to_string(model_.samplers.size()) + " samplers)");
    const tinygltf::Sampler& s = model_.samplers[size_t(t.sampler)];
    const std::string samplerWhere = label_ + ": samplers[" + std::to_string(t.sampler) + "].";
    const auto wrap = [&](int mode, const char* key) {
      if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::Clamp;
      if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::Mirror;
      if (mode == TINYGLTF_TEXTURE_WRAP_REPEAT) return TextureWrap::Repeat;
      throw SceneError(samplerWhere + key +
                       ": expected 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648 "
                       "(MIRRORED_REPEAT), got " +
                       std::to_string(mode));
    };
    ref.wrapS = wrap(s.wrapS, "wrapS");
    ref.wrapT = wrap(s.wrapT, "wrapT");
    if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) {
      ref.filter = TextureFilter::Nearest;
    } else if (s.magFilter != -1 && s.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR) {
      throw SceneError(samplerWhere + "magFilter: expected 9728 (NEAREST) or 9729 (LINEAR), got " +
                       std::to_string(s.magFilter));
    }
  }
  int texCoord = slot.texCoord;
  // KHR_texture_transform, uv' = T R S uv in glTF's uv (v down the image), brought into
  // candela's (v up: v = 1 - glTF's v, docs/scene-format.md, Textures): the same scale and
  // rotation, and the offset where candela's uv (0, 0), glTF's (0, 1), lands.
  if (const tinygltf::Value* transform =
          slot.extensions ? extension(*slot.extensions, "KHR_texture_transform") : nullptr) {
    const std::string tw = label_ + ": " + where + ".extensions.KHR_texture_transform";
    double offset[2] = {0, 0}, scale[2] = {1, 1};
    for (const char* key : {"offset", "scale"}) {
      if (!transform->Has(key)) continue;
      const tinygltf::Value& pair = transform->Get(key);
      double* out = key[0] == 'o' ? offset : scale;
      for (int i = 0; i < 2; ++i) {
        const tinygltf::Value& v =
            pair.IsArray() && pair.ArrayLen() == 2 ? pair.Get(i) : tinygltf::Value();
        out[i] = v.IsNumber() ? v.GetNumberAsDouble() : NAN;
        if (!std::isfinite(out[i]) || (key[0] == 's' && out[i] == 0.0))
          throw SceneError(tw + "." + key + ": expected two finite numbers" +
                           (key[0] == 's' ? ", neither 0" : ""));
      }
    }
    const double rotation = extensionNumber(transform, "rotation", 0.0, tw);
    const double set = extensionNumber(transform, "texCoord", texCoord, tw);
    if (!(set >= 0.0 && set < 1e6 && set == std::floor(set))) {
      throw SceneError(tw + ".texCoord: expected the number of a texture coordinate set, got " +
                       formatNumber(set));
    }
    texCoord = int(set);
    const double c = std::cos(rotation), s = std::sin(rotation);
    ref.scaleU = float(scale[0]);
    ref.scaleV = float(scale[1]);
    ref.rotationCos = float(c);
    ref.rotationSin = float(s);
    ref.offsetU = float(offset[0] - s * scale[1]);
    ref.offsetV = float(1.0 - c * scale[1] - offset[1]);
  }
  if (texCoord != 0)
    warnOnce(where + " reads TEXCOORD_" + std::to_string(texCoord) +
             "; candela reads TEXCOORD_0 for every texture");
  return ref;
}

TextureRef GltfMaterialReader::derived(
    const TextureRef& ref, const std::string& what,
    const std::function<float(const TextureDesc&, size_t)>& value) {
  const TextureDesc& source = textures_.texture(ref.index);
  const std::string key = source.file + " " + what;
  const LoadedTexture made = textures_.add(key, TextureUse::Linear, [&](bool* hasAlpha) {
    TextureDesc t;
    t.file = key;
    t.format = TextureFormat::Float;
    t.width = source.width;
    t.height = source.height;
    t.texelsF.resize(size_t(4) * t.width * t.height);
    for (size_t i = 0; i < size_t(t.width) * t.height; ++i)
      std::fill_n(t.texelsF.begin() + std::ptrdiff_t(4 * i), 4, value(source, i));
    *hasAlpha = false;
    return t;
  });
  TextureRef out = ref;
  out.index = made.index;
  return out;
}

TextureRef GltfMaterialReader::scaledChannel(const TextureRef& ref, uint32_t channel, float factor,
                                             uint32_t* outChannel) {
  *outChannel = channel;
  if (factor == 1.0f) return ref;
  *outChannel = 0;
  return derived(
      ref, "channel " + std::to_string(channel) + " times " + formatNumber(factor),
      [&](const TextureDesc& t, size_t i) { return factor * texelValue(t, i, channel); });
}

Material GltfMaterialReader::surfaceOf(const tinygltf::Material& m, const std::string& where,
                                       bool* baseHasAlpha, TextureRef* metalRough) {
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
  const std::string pbrWhere = where + ".pbrMetallicRoughness";
  Material surface;
  surface.color = colourFactor(pbr.baseColorFactor, label_ + ": " + pbrWhere + ".baseColorFactor");
  for (int c = 0; c < 3; ++c) surface.color[c] = std::fmin(surface.color[c], 1.0f);
  if (pbr.baseColorTexture.index >= 0)
    surface.colorTexture = texture({pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                    &pbr.baseColorTexture.extensions},
                                   TextureUse::Color, pbrWhere + ".baseColorTexture", baseHasAlpha);
  surface.roughness =
      unitFactor(pbr.roughnessFactor, label_ + ": " + pbrWhere + ".roughnessFactor");
  if (pbr.metallicRoughnessTexture.index >= 0) {
    *metalRough =
        texture({pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                 &pbr.metallicRoughnessTexture.extensions},
                TextureUse::Linear, pbrWhere + ".metallicRoughnessTexture");
    surface.roughnessTexture =
        scaledChannel(*metalRough, 1, surface.roughness, &surface.roughnessChannel);
  }
  if (m.normalTexture.index >= 0) {
    surface.normalMap =
        texture({m.normalTexture.index, m.normalTexture.texCoord, &m.normalTexture.extensions},
                TextureUse::Linear, where + ".normalTexture");
    if (m.normalTexture.scale != 1.0)
      warnOnce(where + ".normalTexture.scale " + formatNumber(float(m.normalTexture.scale)) +
               " is read as 1");
  }
  return surface;
}

TextureRef GltfMaterialReader::extensionTexture(const tinygltf::Value& e, const char* key,
                                                TextureUse use, const std::string& where) {
  const tinygltf::Value& info = e.Get(key);
  const auto integer = [&](const char* name, int fallback) {
    return info.Has(name) && info.Get(name).IsInt() ? info.Get(name).GetNumberAsInt() : fallback;
  };
  // tinygltf leaves an extension's textureInfo as plain JSON: its own extensions (a
  // KHR_texture_transform) made a map as a material's textureInfo has them.
  tinygltf::ExtensionMap extensions;
  if (info.Has("extensions") && info.Get("extensions").IsObject()) {
    const tinygltf::Value& object = info.Get("extensions");
    for (const std::string& name : object.Keys()) extensions[name] = object.Get(name);
  }
  return texture({integer("index", -1), integer("texCoord", 0), &extensions}, use,
                 where + "." + key);
}

void GltfMaterialReader::addEmission(const tinygltf::Material& m, const std::string& where,
                                     Material* result) {
  const std::string at = label_ + ": " + where;
  Vec3 emission = colourFactor(m.emissiveFactor, at + ".emissiveFactor");
  if (const tinygltf::Value* e = extension(m.extensions, "KHR_materials_emissive_strength")) {
    const std::string ew = at + ".extensions.KHR_materials_emissive_strength";
    const double strength = extensionNumber(e, "emissiveStrength", 1.0, ew);
    if (!(strength >= 0.0)) throw SceneError(ew + ".emissiveStrength: expected a number >= 0");
    emission = emission * float(strength);
    if (!std::isfinite(emission.x + emission.y + emission.z))
      throw SceneError(ew + ".emissiveStrength: the emission is beyond single precision");
  }
  if (isBlack(emission)) return;
  result->radiance = emission;
  // A double-sided material shows its front on both sides, emission included.
  result->twoSided = m.doubleSided;
  if (m.emissiveTexture.index < 0) return;
  result->emissionTexture =
      texture({m.emissiveTexture.index, m.emissiveTexture.texCoord, &m.emissiveTexture.extensions},
              TextureUse::Color, where + ".emissiveTexture");
  const std::string beyond =
      firstTexelBeyondFloat(textures_.texture(result->emissionTexture.index), emission);
  if (!beyond.empty())
    throw SceneError(at + ".emissiveTexture: the texture's " + beyond +
                     " is beyond single precision");
}

Material GltfMaterialReader::unlitOf(const tinygltf::Material& m, const Material& surface) {
  Material unlit;
  unlit.type = MaterialType::Emissive;
  unlit.radiance = surface.color;
  unlit.emissionTexture = surface.colorTexture;
  unlit.twoSided = m.doubleSided;
  prepareMaterial(&unlit);
  return unlit;
}

void GltfMaterialReader::addAlpha(const tinygltf::Material& m, const TextureRef& baseTexture,
                                  bool baseHasAlpha, const std::string& where, Material* result) {
  if (m.alphaMode != "BLEND" && m.alphaMode != "MASK") return;
  const std::vector<double>& base = m.pbrMetallicRoughness.baseColorFactor;
  const float factor = base.size() > 3 ? float(base[3]) : 1.0f;
  if (!(factor >= 0.0f && factor <= 1.0f))
    throw SceneError(label_ + ": " + where +
                     ".pbrMetallicRoughness.baseColorFactor: expected an alpha between 0 and 1");
  const bool mask = m.alphaMode == "MASK";
  const float cutoff = float(m.alphaCutoff);
  AlphaMask alpha;
  if (baseTexture.index >= 0 && baseHasAlpha) {
    alpha.channel = 3;
    if (mask) {
      alpha.texture = derived(
          baseTexture, "alpha times " + formatNumber(factor) + " cut at " + formatNumber(cutoff),
          [&](const TextureDesc& t, size_t i) {
            return factor * texelValue(t, i, 3) >= cutoff ? 1.0f : 0.0f;
          });
    } else {
      alpha.constant = factor;
      alpha.texture = baseTexture;
    }
  } else {
    alpha.constant = mask ? (factor >= cutoff ? 1.0f : 0.0f) : factor;
  }
  if (isMasked(alpha) && hasEmission(*result))
    warnOnce(where +
             ": the alpha is not used: the material emits, and an emitting surface is a light "
             "over all its area");
  else
    result->alpha = alpha;
}

Material GltfMaterialReader::read(int index, std::vector<Material>* parts) {
  if (index < 0) {  // glTF's default material
    Material metal;
    metal.type = MaterialType::Conductor;
    metal.color = Vec3(1.0f);
    metal.roughness = 1.0f;
    prepareMaterial(&metal);
    return metal;
  }
  const tinygltf::Material& m = model_.materials[size_t(index)];
  const std::string where = "materials[" + std::to_string(index) + "]";
  for (const auto& [name, value] : m.extensions)
    if (!kReadExtensions.count(name))
      warnOnce(where + (m.name.empty() ? "" : " \"" + m.name + "\"") + ": " + name +
               " is not rendered");
  bool baseHasAlpha = false;
  TextureRef metalRough;
  Material surface = surfaceOf(m, where, &baseHasAlpha, &metalRough);
  if (extension(m.extensions, "KHR_materials_unlit")) {
    Material unlit = unlitOf(m, surface);
    addAlpha(m, surface.colorTexture, baseHasAlpha, where, &unlit);
    return unlit;
  }
  addCoat(m, where, &surface);
  addSheen(m, where, &surface);
  const Material anisotropic = anisotropicOf(m, surface, metalRough, where);
  const Shading dielectric = dielectricOf(m, surface, anisotropic, where);

  // Metalness: a mix of the dielectric and a conductor of the base colour.
  const float metallic = unitFactor(m.pbrMetallicRoughness.metallicFactor,
                                    label_ + ": " + where + ".pbrMetallicRoughness.metallicFactor");
  Material metal = anisotropic;
  metal.type = MaterialType::Conductor;
  prepareMaterial(&metal);
  if (anisotropic.anisotropy > 0.0f && (metallic < 1.0f || metalRough.index >= 0) &&
      dielectric.material.type != MaterialType::Glass)
    warnOnce(where +
             ".extensions.KHR_materials_anisotropy: the dielectric's reflection stays "
             "isotropic (candela's plastic takes no anisotropy)");
  Shading shading = dielectric;
  if (metalRough.index >= 0 && metallic > 0.0f) {
    uint32_t channel = 0;
    const TextureRef map = scaledChannel(metalRough, 2, metallic, &channel);
    shading = mixOf(dielectric, {metal, {}}, metallic, map, channel);
  } else if (metalRough.index < 0 && metallic == 1.0f) {
    shading = {metal, {}};
  } else if (metalRough.index < 0 && metallic > 0.0f) {
    shading = mixOf(dielectric, {metal, {}}, metallic, TextureRef(), 0);
  }
  addEmission(m, where, &shading.material);
  addAlpha(m, surface.colorTexture, baseHasAlpha, where, &shading.material);
  return place(shading, parts);
}

}  // namespace candela
