// glTF's material extensions that add to the metallic-roughness model: the index
// (KHR_materials_ior) and specular reflectance (KHR_materials_specular) of the plastic, diffuse
// and specular transmission, the glass's volume and dispersion, anisotropy, the clear coat and the
// sheen; see gltf_materials.h.
#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "render/bsdf_sheen.h"
#include "render/material_prepare.h"
#include "scene/cauchy_index.h"
#include "scene/read/gltf_extension_values.h"
#include "scene/read/gltf_materials.h"
#include "scene/scene_error.h"

namespace candela {

double GltfMaterialReader::fileIorOf(const tinygltf::Material& m, const std::string& where) {
  const tinygltf::Value* e = extension(m.extensions, "KHR_materials_ior");
  if (!e) return 1.5;
  const double value =
      extensionNumber(e, "ior", 1.5, label_ + ": " + where + ".extensions.KHR_materials_ior");
  if (value == 0.0 || value >= 1.0) return value;
  warnOnce(where + ".extensions.KHR_materials_ior.ior " + formatNumber(float(value)) +
           " is read as 1.5 (glTF's index is 0 or at least 1)");
  return 1.5;
}

float GltfMaterialReader::plasticIorOf(const tinygltf::Material& m, double ior,
                                       const std::string& where, bool* scaled) {
  const tinygltf::Value* e = extension(m.extensions, "KHR_materials_specular");
  const std::string sw = where + ".extensions.KHR_materials_specular";
  const float factor = extensionFactor(e, "specularFactor", 1.0, label_ + ": " + sw);
  const Vec3 colour =
      extensionColour(e, "specularColorFactor", Vec3(1.0f), INFINITY, label_ + ": " + sw);
  for (const char* key : {"specularTexture", "specularColorTexture"})
    if (e && e->Has(key))
      warnOnce(sw + "." + key + " is not rendered (a plastic has one index): read as white");
  const bool white = colour.x == 1.0f && colour.y == 1.0f && colour.z == 1.0f;
  *scaled = factor != 1.0f || !white;
  if (factor == 1.0f && white && ior > 1.0 && ior < 1e3) return float(ior);
  // F0, each channel clamped to 1 as glTF's dielectric_f0 is, then its luminance.
  const double f0 = ior == 0.0 ? 1.0 : ((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0));
  Vec3 tinted;
  for (int c = 0; c < 3; ++c) tinted[c] = float(std::min(f0 * colour[c], 1.0));
  if (tinted.x != tinted.y || tinted.y != tinted.z)
    warnOnce(sw + ".specularColorFactor " + formatVec3(colour) +
             " tints the reflection by its luminance alone (candela's plastic reflects white)");
  const double reflectance = double(factor) * luminance(tinted);
  if (!(reflectance > 0.0)) return 0.0f;
  // The index of that reflectance at normal incidence, below 1000 (F0 0.996).
  const double r = std::min(std::sqrt(reflectance), 0.998);
  return float((1.0 + r) / (1.0 - r));
}

Shading GltfMaterialReader::dielectricOf(const tinygltf::Material& m, const Material& surface,
                                         const Material& anisotropic, const std::string& where) {
  double ior = fileIorOf(m, where);
  Material plastic = surface;
  bool specularScaled = false;
  plastic.ior = plasticIorOf(m, ior, where, &specularScaled);
  plastic.type = plastic.ior > 0.0f ? MaterialType::Plastic : MaterialType::Diffuse;
  if (plastic.type == MaterialType::Diffuse) {  // a base that nothing reflects over
    plastic.ior = 1.5f;
    plastic.roughness = 0.0f;
    plastic.roughnessTexture = TextureRef();
  }
  prepareMaterial(&plastic);
  const Shading opaque = withDiffuseTransmission(m, surface, plastic, where);
  const tinygltf::Value* e = extension(m.extensions, "KHR_materials_transmission");
  if (!e) return opaque;
  const std::string tw = where + ".extensions.KHR_materials_transmission";
  const float transmission = extensionFactor(e, "transmissionFactor", 0.0, label_ + ": " + tw);
  if (!(transmission > 0.0f)) return opaque;
  TextureRef map;
  uint32_t channel = 0;
  if (e->Has("transmissionTexture"))
    map = scaledChannel(extensionTexture(*e, "transmissionTexture", TextureUse::Linear, tw), 0,
                        transmission, &channel);
  if (surface.coatWeight > 0.0f || hasSheen(surface))
    warnOnce(tw + ": the transmitted part has no clear coat or sheen (candela's glass takes none)");
  if (specularScaled)
    warnOnce(tw +
             ": the transmitted part reflects as its index says (KHR_materials_specular "
             "scales the plastic's reflection alone)");
  if (ior == 0.0 || ior >= 1e3) {
    warnOnce(where + ".extensions.KHR_materials_ior.ior " + formatNumber(float(ior)) +
             " is read as 1.5 for the transmitted part (candela's glass takes an index from 1 "
             "to 1000)");
    ior = 1.5;
  }
  Material glass;
  glass.type = MaterialType::Glass;
  glass.ior = float(ior);
  glass.color = surface.color;
  glass.roughness = anisotropic.roughness;
  glass.roughnessTexture = anisotropic.roughnessTexture;
  glass.roughnessChannel = anisotropic.roughnessChannel;
  glass.anisotropy = anisotropic.anisotropy;
  glass.anisotropyRotation = anisotropic.anisotropyRotation;
  glass.normalMap = surface.normalMap;
  addVolume(m, where, &glass);
  if (surface.colorTexture.index >= 0)
    warnOnce(where +
             ": the transmitted light is tinted by baseColorFactor alone (candela's glass takes "
             "no colour texture)");
  prepareMaterial(&glass);
  if (transmission == 1.0f && map.index < 0) return {glass, {}};
  return mixOf(opaque, {glass, {}}, transmission, map, channel);
}

Shading GltfMaterialReader::withDiffuseTransmission(const tinygltf::Material& m,
                                                    const Material& surface,
                                                    const Material& plastic,
                                                    const std::string& where) {
  const tinygltf::Value* e = extension(m.extensions, "KHR_materials_diffuse_transmission");
  if (!e) return {plastic, {}};
  const std::string dw = where + ".extensions.KHR_materials_diffuse_transmission";
  const float factor = extensionFactor(e, "diffuseTransmissionFactor", 0.0, label_ + ": " + dw);
  if (!(factor > 0.0f)) return {plastic, {}};
  // The share that glTF transmits diffusely, as a sheet that lets its colour through and reflects
  // nothing: a mix with the plastic by the share (times the texture's alpha channel).
  Material sheet;
  sheet.type = MaterialType::Translucent;
  sheet.color = Vec3(0.0f);
  sheet.transmittance =
      extensionColour(e, "diffuseTransmissionColorFactor", Vec3(1.0f), 1.0f, label_ + ": " + dw);
  if (e->Has("diffuseTransmissionColorTexture"))
    sheet.transmittanceTexture =
        extensionTexture(*e, "diffuseTransmissionColorTexture", TextureUse::Color, dw);
  sheet.normalMap = surface.normalMap;
  prepareMaterial(&sheet);
  warnOnce(dw + ": the diffusely transmitted share has no specular reflection" +
           (surface.coatWeight > 0.0f || hasSheen(surface) ? ", clear coat or sheen" : "") +
           " (candela's translucent surface takes no coat)");
  TextureRef map;
  uint32_t channel = 0;
  if (e->Has("diffuseTransmissionTexture"))
    map = scaledChannel(extensionTexture(*e, "diffuseTransmissionTexture", TextureUse::Linear, dw),
                        3, factor, &channel);
  if (factor == 1.0f && map.index < 0) return {sheet, {}};
  return mixOf({plastic, {}}, {sheet, {}}, factor, map, channel);
}

void GltfMaterialReader::addVolume(const tinygltf::Material& m, const std::string& where,
                                   Material* glass) {
  // KHR_materials_volume: attenuationColor is what white light keeps after attenuationDistance
  // inside, as candela's transmission_depth (thicknessFactor is for renderers without the
  // geometry's own thickness).
  if (const tinygltf::Value* e = extension(m.extensions, "KHR_materials_volume")) {
    const std::string vw = label_ + ": " + where + ".extensions.KHR_materials_volume";
    const double distance = e->Has("attenuationDistance")
                                ? extensionNumber(e, "attenuationDistance", 0.0, vw)
                                : INFINITY;
    if (!(distance > 0.0)) throw SceneError(vw + ".attenuationDistance: expected a number > 0");
    Vec3 kept(1.0f);
    if (e->Has("attenuationColor")) {
      const tinygltf::Value& c = e->Get("attenuationColor");
      for (int i = 0; i < 3; ++i) {
        const tinygltf::Value& v = c.IsArray() && c.ArrayLen() == 3 ? c.Get(i) : tinygltf::Value();
        kept[i] = v.IsNumber() ? float(v.GetNumberAsDouble()) : NAN;
        if (!(kept[i] > 0.0f && kept[i] <= 1.0f))
          throw SceneError(vw + ".attenuationColor: expected three numbers in (0, 1]");
      }
    }
    if (std::isfinite(distance))
      for (int c = 0; c < 3; ++c) glass->absorption[c] = float(-std::log(kept[c]) / distance);
    if (!isFinite(glass->absorption))
      throw SceneError(vw + ": absorbs more than single precision can say");
  }
  // KHR_materials_dispersion: 20 / the Abbe number, at the index's d line.
  if (const tinygltf::Value* e = extension(m.extensions, "KHR_materials_dispersion")) {
    const std::string dw = label_ + ": " + where + ".extensions.KHR_materials_dispersion";
    const double dispersion = extensionNumber(e, "dispersion", 0.0, dw);
    if (!(dispersion >= 0.0 && dispersion <= 20.0))
      throw SceneError(dw + ".dispersion: expected a number in [0, 20] (20 / the Abbe number)");
    if (dispersion > 0.0)
      for (int c = 0; c < 3; ++c)
        glass->channelIor[c] = float(cauchyIndex(glass->ior, 20.0 / dispersion, kChannelLambda[c]));
  }
}

Material GltfMaterialReader::anisotropicOf(const tinygltf::Material& m, const Material& surface,
                                           const TextureRef& metalRough, const std::string& where) {
  const tinygltf::Value* e = extension(m.extensions, "KHR_materials_anisotropy");
  if (!e) return surface;
  const std::string aw = where + ".extensions.KHR_materials_anisotropy";
  const float strength = extensionFactor(e, "anisotropyStrength", 0.0, label_ + ": " + aw);
  const double rotation = extensionNumber(e, "anisotropyRotation", 0.0, label_ + ": " + aw);
  if (e->Has("anisotropyTexture"))
    warnOnce(aw +
             ".anisotropyTexture is not rendered: the anisotropy lies along the tangent "
             "turned by anisotropyRotation, of strength anisotropyStrength");
  // glTF's alphas: the tangent's mix(alpha, 1, strength^2), the bitangent's alpha itself; as
  // candela's roughness and anisotropy (render/microfacet.h, tangentAlpha): the bitangent's alpha
  // is (1 - anisotropy) times the tangent's, and roughness^2 their root mean square.
  const double alpha = double(surface.roughness) * surface.roughness;
  const double along = alpha + double(strength) * strength * (1.0 - alpha);
  if (!(strength > 0.0f) || !(along > alpha)) return surface;
  const double across = alpha / along;
  const double rms = along * std::sqrt(0.5 * (1.0 + across * across));
  Material anisotropic = surface;
  anisotropic.roughness = float(std::sqrt(rms));
  anisotropic.anisotropy = float(1.0 - across);
  anisotropic.anisotropyRotation = float(std::fmod(rotation, 2.0 * kPiDouble));
  if (metalRough.index >= 0 && surface.roughness > 0.0f) {
    // The texture scaled so that a texel at the factor's roughness gets exactly glTF's alphas;
    // the others keep glTF's bitangent alpha, and their tangent's is the factor's ratio times it.
    anisotropic.roughnessTexture =
        scaledChannel(metalRough, 1, anisotropic.roughness, &anisotropic.roughnessChannel);
    warnOnce(aw +
             ": with a roughness texture, the ratio of the tangent's roughness to the "
             "bitangent's is the roughnessFactor's everywhere");
  }
  return anisotropic;
}

void GltfMaterialReader::addCoat(const tinygltf::Material& m, const std::string& where,
                                 Material* surface) {
  const tinygltf::Value* e = extension(m.extensions, "KHR_materials_clearcoat");
  if (!e) return;
  const std::string cw = where + ".extensions.KHR_materials_clearcoat";
  surface->coatWeight = extensionFactor(e, "clearcoatFactor", 0.0, label_ + ": " + cw);
  surface->coatRoughness = extensionFactor(e, "clearcoatRoughnessFactor", 0.0, label_ + ": " + cw);
  surface->coatIor = 1.5f;  // the extension's fixed index
  if (surface->coatWeight > 0.0f && e->Has("clearcoatTexture")) {
    // The weight is the texture's red channel times the factor.
    surface->coatTexture =
        scaledChannel(extensionTexture(*e, "clearcoatTexture", TextureUse::Linear, cw), 0,
                      surface->coatWeight, &surface->coatChannel);
    surface->coatWeight = 1.0f;
  }
  if (surface->coatWeight > 0.0f && surface->coatRoughness > 0.0f &&
      e->Has("clearcoatRoughnessTexture")) {
    // The roughness is the texture's green channel times the factor (a factor of 0 leaves the
    // coat smooth).
    surface->coatRoughnessTexture =
        scaledChannel(extensionTexture(*e, "clearcoatRoughnessTexture", TextureUse::Linear, cw), 1,
                      surface->coatRoughness, &surface->coatRoughnessChannel);
  }
  if (surface->coatWeight > 0.0f && e->Has("clearcoatNormalTexture")) {
    // The coat's own normals; without them it lies smooth over the base's normal texture.
    surface->coatNormalMap = extensionTexture(*e, "clearcoatNormalTexture", TextureUse::Linear, cw);
    const tinygltf::Value& info = e->Get("clearcoatNormalTexture");
    const tinygltf::Value scale =
        info.IsObject() && info.Has("scale") ? info.Get("scale") : tinygltf::Value(1.0);
    if (!scale.IsNumber() || scale.GetNumberAsDouble() != 1.0)
      warnOnce(cw + ".clearcoatNormalTexture.scale is read as 1");
  }
}

void GltfMaterialReader::addSheen(const tinygltf::Material& m, const std::string& where,
                                  Material* surface) {
  const tinygltf::Value* e = extension(m.extensions, "KHR_materials_sheen");
  if (!e) return;
  const std::string sw = where + ".extensions.KHR_materials_sheen";
  surface->sheenColor =
      extensionColour(e, "sheenColorFactor", surface->sheenColor, 1.0f, label_ + ": " + sw);
  surface->sheenRoughness = extensionFactor(e, "sheenRoughnessFactor", 0.0, label_ + ": " + sw);
  // The colour is the texture's (sRGB) times the factor.
  if (hasSheen(*surface) && e->Has("sheenColorTexture"))
    surface->sheenTexture = extensionTexture(*e, "sheenColorTexture", TextureUse::Color, sw);
  // The roughness is the texture's alpha channel times the factor.
  if (hasSheen(*surface) && surface->sheenRoughness > 0.0f && e->Has("sheenRoughnessTexture"))
    surface->sheenRoughnessTexture =
        scaledChannel(extensionTexture(*e, "sheenRoughnessTexture", TextureUse::Linear, sw), 3,
                      surface->sheenRoughness, &surface->sheenRoughnessChannel);
}

}  // namespace candela
