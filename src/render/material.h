// Materials: a plain tag and the parameters of every kind, read by render/bsdf.h.
//
// The scene description and the kernel share this struct: a material has one home. What a
// material derives from its parameters (the plastic's internal reflectance and transmittance
// table) is filled in once on the host by prepareMaterial (render/material_prepare.h).
// Every TextureRef of a Material is named in scene/mesh_layout.cpp's readsTextures, which gives
// a mesh its texture coordinates only where some material reads them.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/device.h"
#include "core/texture.h"
#include "core/vec3.h"
#include "geometry/alpha_mask.h"

namespace candela {

enum class MaterialType : uint32_t {
  Diffuse = 0,
  Conductor = 1,  // the contract's "mirror" is a conductor of roughness 0
  Glass = 2,
  Emissive = 3,
  Plastic = 4,
  // Two materials, one of which a path meets at each hit, chosen by the weight there
  // (render/material_mix.h); never a part of what the BSDF or the lights see.
  Mix = 5,
  // The contract's "diffuse" with a "transmittance": a sheet that reflects `color` and lets
  // `transmittance` through, both diffusely (render/bsdf_diffuse.h). A type of its own so that
  // plain diffuse hits, the most common, never look at the transmittance.
  Translucent = 6,
};

// Samples of the rough plastic's coating transmittance over cos(theta) in [0, 1] (Mitsuba 3's
// MTS_ROUGH_TRANSMITTANCE_RES is 64 for the same table).
constexpr uint32_t kPlasticTableSize = 64;

// Linear interpolation at cos(theta) in a table of kPlasticTableSize samples over cos(theta) in
// [0, 1]: the plastic's and the coat's transmittance, the sheen's albedo.
CANDELA_HDI float cosineTableAt(const float* table, float cosTheta) {
  const float x = minf(maxf(cosTheta, 0.0f), 1.0f) * float(kPlasticTableSize - 1);
  const uint32_t i = x < float(kPlasticTableSize - 2) ? uint32_t(x) : kPlasticTableSize - 2;
  const float w = x - float(i);
  return (1.0f - w) * table[i] + w * table[i + 1];
}

// cosineTableAt in `row`, a table of a set by roughness level, blended by `blend` with the same
// table of the next level, `stride` floats on (0: the row alone).
CANDELA_HDI float levelTableAt(const float* row, uint32_t stride, float blend, float cosTheta) {
  const float t = cosineTableAt(row, cosTheta);
  if (blend == 0.0f) return t;
  return (1.0f - blend) * t + blend * cosineTableAt(row + stride, cosTheta);
}
// A plastic whose roughness is textured has a table per roughness level instead (SceneView::
// plasticCoats): kPlasticCoatLevels rows from the smoothest rough surface (alpha kSmoothAlpha) to
// roughness 1 (render/bsdf_plastic.h, plasticCoatLevelRoughness), each its transmittance table
// and then its internal reflectance.
constexpr uint32_t kPlasticCoatLevels = 32;
constexpr uint32_t kPlasticCoatRow = kPlasticTableSize + 1;
// A sheen's tables, by cos(theta): its lobe's directional albedo, then that of the lobe normalized
// to at most 1 (render/bsdf_sheen.h; Material::sheenAlbedo and sheenKept). A sheen whose
// roughness is textured reads such rows for kSheenLevels alphas, kSheenMinAlpha to 1 evenly spaced
// in log(alpha), as the lobe changes with 1 / alpha (SceneView::sheenTables;
// render/surface_layers.h).
constexpr uint32_t kSheenRow = 2 * kPlasticTableSize;
constexpr uint32_t kSheenLevels = 32;

// The smallest alpha of the sheen's fibres: below it the lobe is a spike at the horizon that
// float cannot hold (sin^(1/a)).
constexpr float kSheenMinAlpha = 1e-3f;

// The alpha of a sheen of roughness `roughness` (render/bsdf_sheen.h).
CANDELA_HDI float sheenAlpha(float roughness) {
  return maxf(roughness * roughness, kSheenMinAlpha);
}

struct Material {
  MaterialType type = MaterialType::Diffuse;
  // Diffuse albedo, conductor reflectance (tinting the metal's Fresnel when `metal`), glass
  // transmission tint or plastic base colour.
  Vec3 color{0.8f};
  float ior = 1.5f;        // glass and plastic: relative index, outside -> inside
  // Glass: the absorption coefficient of its inside, per unit length and colour channel (Beer's
  // law, from "transmission_depth"); 0 where its `color` tints each crossing instead.
  Vec3 absorption{0.0f};
  // Glass with an Abbe number: its index in each colour channel (render/dispersion.h); 0 where
  // it has the one index `ior`.
  Vec3 channelIor{0.0f};
  float roughness = 0.0f;  // conductor, glass, plastic: in [0, 1], alpha = roughness^2
  // Conductor, glass: in [0, 1], how much rougher the surface is along its tangent (where u grows)
  // than across it (render/microfacet.h, tangentAlpha); the tangent turned about the normal by
  // anisotropyRotation radians.
  float anisotropy = 0.0f;
  float anisotropyRotation = 0.0f;
  // Conductor, glass, plastic: a texture whose value (luminance, read linearly) is the roughness
  // in place of `roughness`; the material is then rough everywhere (render/microfacet.h).
  TextureRef roughnessTexture;
  // Which of the roughness texture's channels is the roughness (core/texture.h, textureChannel;
  // glTF packs roughness into G, with metalness in B).
  uint32_t roughnessChannel = kLuminanceChannel;
  bool metal = false;      // conductor: Fresnel of the complex index metalEta + i metalK
  Vec3 metalEta{0.0f}, metalK{0.0f};
  // Radiance emitted from the front side: an emissive material's, or the "emission" of one that
  // reflects too (never a mix's part: a mix's own is its surface's, render/integrator.h).
  Vec3 radiance{0.0f};
  bool twoSided = false;          // emits `radiance` from its back as well (mesh faces only)
  bool hiddenFromCamera = false;  // emissive: camera rays pass it by (a light's "visible": false)
  TextureRef colorTexture;     // a texture that `color` tints (render/surface_color.h)
  TextureRef emissionTexture;  // a texture that `radiance` tints (MTL map_Ke)
  TextureRef normalMap;        // tangent-space normals that tilt the shading normal, or heights
  float bumpHeight = 0.0f;     // != 0: normalMap is a bump map, heights this many units a unit
  AlphaMask alpha;          // how much of the surface is there (geometry/alpha_mask.h)
  // Mix: the materials it mixes (indices into the scene's materials, each after the mix's own)
  // and the share of the second, `mixWeight` or its texture's value (luminance or the channel
  // mixWeightChannel).
  uint32_t mixParts[2] = {0, 0};
  float mixWeight = 0.5f;
  TextureRef mixWeightTexture;
  uint32_t mixWeightChannel = kLuminanceChannel;

  // Layers over the diffuse, conductor or plastic material: a clear coat (render/bsdf_coat.h)
  // on the share coatWeight of the surface (0: none), a dielectric of index coatIor and roughness
  // coatRoughness (alpha = roughness^2); a sheen (render/bsdf_sheen.h) of colour sheenColor (0:
  // none) and fibres of roughness sheenRoughness. Their tables are at the end. (Placed here, not
  // beside `type`: shifting the fields a diffuse hit reads cost the Cornell box about 3%.)
  float coatWeight = 0.0f;
  float coatRoughness = 0.0f;
  float coatIor = 1.5f;
  Vec3 sheenColor{0.0f};
  float sheenRoughness = 0.5f;
  // Translucent: the share of light, by colour, that passes diffusely through to the other side
  // (render/bsdf_diffuse.h), beside the share `color` that it reflects, and a texture that it
  // tints (render/surface_color.h).
  Vec3 transmittance{0.0f};
  TextureRef transmittanceTexture;
  // A texture whose value (luminance, or the channel coatChannel) is the coat's weight in place of
  // coatWeight (then 1), and one the sheen colour tints (render/surface_layers.h).
  TextureRef coatTexture;
  uint32_t coatChannel = kLuminanceChannel;
  TextureRef sheenTexture;
  // A texture whose value (luminance, or the channel coatRoughnessChannel) is the coat's roughness
  // in place of coatRoughness: the coat is then rough everywhere, and its transmittance comes from
  // the tables by roughness level at SceneView::plasticCoats + coatTable (the plastic's, of index
  // coatIor; set when the scene is flattened, -1: none).
  TextureRef coatRoughnessTexture;
  uint32_t coatRoughnessChannel = kLuminanceChannel;
  int32_t coatTable = -1;
  // Tangent-space normals that tilt the coat's normal (render/normal_map.h, coatNormal); without
  // them the coat lies along the surface's shading normal, unmapped by normalMap.
  TextureRef coatNormalMap;
  // A texture whose value (luminance, or the channel sheenRoughnessChannel) is the sheen's
  // roughness in place of sheenRoughness, its tables then read by level (kSheenLevels).
  TextureRef sheenRoughnessTexture;
  uint32_t sheenRoughnessChannel = kLuminanceChannel;

  // Plastic, derived (prepareMaterial): the diffuse light's chance to be reflected back down by
  // the coating from inside, and the coating's transmittance from outside by cos(theta).
  float plasticInternalReflectance = 0.0f;
  float plasticTransmittance[kPlasticTableSize] = {};
  // Plastic with a roughnessTexture: where its coat rows begin in SceneView::plasticCoats (set
  // when the scene is flattened; -1: none).
  int32_t plasticCoatTable = -1;

  // Layers, derived (prepareMaterial), by cos(theta): a rough coat's transmittance; the sheen
  // lobe's directional albedo, and that of the lobe normalized to at most 1 (one row of kSheenRow:
  // sheenKept follows sheenAlbedo).
  float coatTransmittance[kPlasticTableSize] = {};
  float sheenAlbedo[kPlasticTableSize] = {};
  float sheenKept[kPlasticTableSize] = {};

  // Glass: the scattering coefficient of its inside, per unit length and colour channel, beside
  // `absorption`, and the Henyey-Greenstein g of its phase function (render/medium.h,
  // render/phase_function.h); 0: the inside only absorbs. (At the end, where no other material's
  // hit reads past them.)
  Vec3 scattering{0.0f};
  float scatteringAnisotropy = 0.0f;
};
static_assert(offsetof(Material, sheenKept) ==
                  offsetof(Material, sheenAlbedo) + kPlasticTableSize * sizeof(float),
              "a sheen's two tables make one row");

// Whether a surface of material m emits light: an emissive material, or one that reflects and
// emits as well (its "emission"). What emits is a light (scene/flatten_lights.cpp).
CANDELA_HDI bool hasEmission(const Material& m) { return !isBlack(m.radiance); }

// Whether glass m has a medium inside (one that absorbs, scatters or both), which a path enters by
// a transmission through its surface (render/integrator.h).
CANDELA_HDI bool hasMedium(const Material& m) {
  return !isBlack(m.absorption) || !isBlack(m.scattering);
}

// The medium (a material index, or -1 for none) that a ray leaving a surface of glass m (material
// `index`) along w travels in: m's inside where w goes against the outward normal ng and m holds a
// medium, else the outside, which holds none.
CANDELA_HDI int32_t mediumAlong(const Material& m, uint32_t index, const Vec3& w, const Vec3& ng) {
  return dot(w, ng) < 0.0f && hasMedium(m) ? int32_t(index) : -1;
}

}  // namespace candela
