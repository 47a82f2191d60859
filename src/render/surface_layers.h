// The layers over a material at a surface point (render/bsdf_coat.h, render/bsdf_sheen.h): the
// coat's weight and roughness and the sheen's colour and roughness, each the material's own, or
// where it has a texture for it, the texture's value there (a number from the texture's luminance
// or a channel, at most 1, a coat's textured roughness at least the smoothest rough one; the sheen
// colour times the texture's colour, each channel at most 1), with the tables they read.
#pragma once

#include "core/texture.h"
#include "geometry/surface.h"
#include "geometry/surface_uv.h"
#include "render/bsdf_plastic.h"
#include "render/material.h"
#include "render/microfacet.h"
#include "render/scene_view.h"

namespace candela {

struct SurfaceLayers {
  float coat = 0.0f;
  Vec3 sheen{0.0f};
  // The coat's roughness, and its transmittance table by cos(theta) (a rough coat's: blended by
  // coatBlend with the row after it where the roughness is textured, render/bsdf_plastic.h's
  // coatTableAt).
  float coatRoughness = 0.0f;
  float coatBlend = 0.0f;
  const float* coatTransmittance = nullptr;
  // The sheen's roughness, and its row of tables (kSheenRow: albedo, then kept), blended by
  // sheenBlend with the next level's where the roughness is textured.
  float sheenRoughness = 0.0f;
  float sheenBlend = 0.0f;
  const float* sheenTable = nullptr;
  // The normal about which the coat reflects, in the world, where it is not the shading normal
  // the material beneath has (render/normal_map.h, applyNormalMaps); zero where it is.
  Vec3 coatNormal{0.0f};
};

// The layers of a material without textures for them.
CANDELA_HDI SurfaceLayers untexturedLayers(const Material& m) {
  return {m.coatWeight,     m.sheenColor, m.coatRoughness, 0.0f,      m.coatTransmittance,
          m.sheenRoughness, 0.0f,         m.sheenAlbedo,   Vec3(0.0f)};
}

// Whether m has a texture for one of its layers' values.
CANDELA_HDI bool hasLayerTextures(const Material& m) {
  return m.coatTexture.index >= 0 || m.sheenTexture.index >= 0 ||
         m.coatRoughnessTexture.index >= 0 || m.sheenRoughnessTexture.index >= 0;
}

// The roughness of level `level` of the sheen's tables by roughness (SceneView::sheenTables):
// alphas from kSheenMinAlpha to 1, evenly spaced in log(alpha).
CANDELA_HDI float sheenLevelRoughness(uint32_t level) {
  return sqrtf(kSheenMinAlpha *
               powf(1.0f / kSheenMinAlpha, float(level) / float(kSheenLevels - 1)));
}

// Where a sheen of roughness `roughness` lies among the levels, in [0, kSheenLevels - 1]: level x
// and x + 1 blended by the fraction of x.
CANDELA_HDI float sheenLevelAt(float roughness) {
  const float x = logf(sheenAlpha(roughness) * (1.0f / kSheenMinAlpha)) *
                  (float(kSheenLevels - 1) / logf(1.0f / kSheenMinAlpha));
  return minf(maxf(x, 0.0f), float(kSheenLevels - 1));
}

// m's layers at `sp`, its coat about `coatNormal` (applyNormalMaps: zero for sp.ns). Out of
// line: most materials have no layers, and few layers have textures.
CANDELA_HD_NOINLINE inline SurfaceLayers surfaceLayers(const SceneView& scene, const Material& m,
                                                       const Hit& hit, const SurfacePoint& sp,
                                                       const Vec3& coatNormal) {
  SurfaceLayers layers = untexturedLayers(m);
  layers.coatNormal = coatNormal;
  if (!hasLayerTextures(m)) return layers;
  const Vec2 uv = surfaceUv(scene, hit, sp);
  if (m.coatTexture.index >= 0)
    layers.coat = minf(textureChannel(lookupTexture(scene.texturePool(), m.coatTexture, uv.x, uv.y),
                                      m.coatChannel),
                       1.0f);
  if (m.sheenTexture.index >= 0)
    layers.sheen =
        min(Vec3(1.0f),
            layers.sheen * lookupTexture(scene.texturePool(), m.sheenTexture, uv.x, uv.y).rgb);
  if (m.coatRoughnessTexture.index >= 0) {
    const TextureSample s = lookupTexture(scene.texturePool(), m.coatRoughnessTexture, uv.x, uv.y);
    layers.coatRoughness =
        minf(maxf(textureChannel(s, m.coatRoughnessChannel), smoothestRoughRoughness()), 1.0f);
    layers.coatTransmittance =
        coatTableRow(scene.plasticCoats + m.coatTable, layers.coatRoughness, &layers.coatBlend);
  }
  if (m.sheenRoughnessTexture.index >= 0) {
    const TextureSample s = lookupTexture(scene.texturePool(), m.sheenRoughnessTexture, uv.x, uv.y);
    layers.sheenRoughness = minf(textureChannel(s, m.sheenRoughnessChannel), 1.0f);
    const float x = sheenLevelAt(layers.sheenRoughness);
    const uint32_t level = x < float(kSheenLevels - 2) ? uint32_t(x) : kSheenLevels - 2;
    layers.sheenBlend = x - float(level);
    layers.sheenTable = scene.sheenTables + level * kSheenRow;
  }
  return layers;
}

}  // namespace candela
