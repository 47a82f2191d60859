// glTF 2.0 materials as candela's (docs/scene-format.md, glTF meshes): the metallic-roughness
// model is a mix, by metalness, of a plastic (the dielectric base under its coat, glTF's
// fresnel_mix) and a conductor whose reflectance is the base colour; KHR_materials_transmission
// mixes glass into the dielectric, KHR_materials_ior sets its index, KHR_materials_volume its
// absorption, KHR_materials_dispersion its Abbe number, KHR_materials_specular the plastic's
// reflectance, KHR_materials_anisotropy the conductor's and glass's anisotropy,
// KHR_materials_diffuse_transmission a translucent sheet mixed with the plastic, and
// KHR_materials_clearcoat and KHR_materials_sheen a coat and a sheen over the plastic and the
// conductor; KHR_materials_unlit makes an emitter of the base colour. Normal maps, emission
// (KHR_materials_emissive_strength), alpha (MASK and BLEND) and KHR_texture_transform are read;
// what candela does not render is named in a warning. The extensions that add to the
// metallic-roughness model are read in gltf_material_extensions.cpp.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "render/material.h"
#include "scene/read/texture_reader.h"
#include "scene/read/tiny_gltf_config.h"

namespace candela {

// A material and, where it is a mix, its two parts: placed into a mesh's parts only once whole,
// so that every mix's parts follow it there (render/material_mix.h).
struct Shading {
  Material material;
  std::vector<Shading> parts;
};

class GltfMaterialReader {
 public:
  // `label` names the file in messages, `folder` is where its URIs are resolved, `embedded` holds
  // the bytes of its images held in the file (data URIs and buffer views) by image index.
  GltfMaterialReader(const tinygltf::Model& model, std::string label, std::string folder,
                     const std::map<int, std::string>& embedded, TextureLoader& textures,
                     std::vector<std::string>* warnings)
      : model_(model),
        label_(std::move(label)),
        folder_(std::move(folder)),
        embedded_(embedded),
        textures_(textures),
        warnings_(warnings) {}

  // The material of glTF material `index` (-1: glTF's default material, a white rough metal),
  // its mixes' parts appended to *parts.
  Material read(int index, std::vector<Material>* parts);

 private:
  struct TextureSlot {
    int index = -1, texCoord = 0;
    const tinygltf::ExtensionMap* extensions = nullptr;
  };
  TextureRef texture(const TextureSlot& slot, TextureUse use, const std::string& where,
                     bool* hasAlpha = nullptr);
  // The texture that the textureInfo `key` of extension object `e` names (`where` its path).
  TextureRef extensionTexture(const tinygltf::Value& e, const char* key, TextureUse use,
                              const std::string& where);
  // A texture made from `ref`'s, each texel's four channels `value` of the source's texel i,
  // read once per (ref's file, `what`).
  TextureRef derived(const TextureRef& ref, const std::string& what,
                     const std::function<float(const TextureDesc&, size_t)>& value);
  // `ref`'s channel times `factor`, as a texture of its own where factor is not 1 (glTF
  // multiplies its textures by factors that candela's fields do not take), into *channel.
  TextureRef scaledChannel(const TextureRef& ref, uint32_t channel, float factor,
                           uint32_t* outChannel);
  // What every part shares: the base colour, the roughness and the normal map; the
  // metallic-roughness texture into *metalRough.
  Material surfaceOf(const tinygltf::Material& m, const std::string& where, bool* baseHasAlpha,
                     TextureRef* metalRough);
  // KHR_materials_ior's index as the file gives it: 1.5 where absent; 0 (an infinite index, as
  // specular-glossiness materials convert) or at least 1, else read as 1.5 with a warning.
  double fileIorOf(const tinygltf::Material& m, const std::string& where);
  // The plastic's index: the one whose reflectance at normal incidence is glTF's dielectric F0,
  // ((ior - 1) / (ior + 1))^2 for the file's index `ior` (1 for an ior of 0), times
  // KHR_materials_specular's colour (its luminance: candela's plastic reflects white) and factor;
  // 0 where that is 0 (a diffuse base). *scaled: whether the extension's factor or colour scale
  // the reflectance (they are not glTF's defaults).
  float plasticIorOf(const tinygltf::Material& m, double ior, const std::string& where,
                     bool* scaled);
  // The surface with KHR_materials_anisotropy's strength and rotation as its anisotropy, for the
  // parts that take one (the conductor and the glass); the surface itself without.
  Material anisotropicOf(const tinygltf::Material& m, const Material& surface,
                         const TextureRef& metalRough, const std::string& where);
  // The plastic (a diffuse base where KHR_materials_specular leaves it nothing to reflect), with
  // its diffuse transmission, or with transmission the glass (rough as `anisotropic`) or a mix of
  // the two.
  Shading dielectricOf(const tinygltf::Material& m, const Material& surface,
                       const Material& anisotropic, const std::string& where);
  // `plastic`, or with KHR_materials_diffuse_transmission a mix of it and a translucent sheet of
  // the transmission's colour by its factor (a sheet alone where the factor is 1).
  Shading withDiffuseTransmission(const tinygltf::Material& m, const Material& surface,
                                  const Material& plastic, const std::string& where);
  // A glass's absorption (KHR_materials_volume) and dispersion (KHR_materials_dispersion).
  void addVolume(const tinygltf::Material& m, const std::string& where, Material* glass);
  // KHR_materials_clearcoat's factors, as the coat of the opaque parts (the plastic and the
  // conductor; candela's glass takes none).
  void addCoat(const tinygltf::Material& m, const std::string& where, Material* surface);
  // KHR_materials_sheen's factors, likewise.
  void addSheen(const tinygltf::Material& m, const std::string& where, Material* surface);
  void addEmission(const tinygltf::Material& m, const std::string& where, Material* result);
  // KHR_materials_unlit: an emitter of the base colour (times its texture), which the camera sees
  // as that colour; from both sides where the material is double-sided.
  Material unlitOf(const tinygltf::Material& m, const Material& surface);
  void addAlpha(const tinygltf::Material& m, const TextureRef& baseTexture, bool baseHasAlpha,
                const std::string& where, Material* result);
  void warnOnce(const std::string& message);

  const tinygltf::Model& model_;
  std::string label_, folder_;
  const std::map<int, std::string>& embedded_;
  TextureLoader& textures_;
  std::vector<std::string>* warnings_;
  std::set<std::string> warned_;
};

}  // namespace candela
