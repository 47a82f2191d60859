// The layers over a material at a surface point (render/bsdf_coat.h, render/bsdf_sheen.h): the
// coat's weight and the sheen's colour, each the material's own, or where it has a texture for
// it, the texture's value there (the coat's from its luminance or a channel, at most 1; the sheen
// colour times the texture's colour, each channel at most 1).
#pragma once

#include "core/texture.h"
#include "geometry/surface.h"
#include "geometry/surface_uv.h"
#include "render/material.h"
#include "render/scene_view.h"

namespace candela {

struct SurfaceLayers {
  float coat = 0.0f;
  Vec3 sheen{0.0f};
};

// The layers of a material without textures for them.
CANDELA_HDI SurfaceLayers untexturedLayers(const Material& m) {
  return {m.coatWeight, m.sheenColor};
}

// Out of line: most materials have no layers, and few layers have textures.
CANDELA_HD_NOINLINE inline SurfaceLayers surfaceLayers(const SceneView& scene, const Material& m,
                                                       const Hit& hit, const SurfacePoint& sp) {
  SurfaceLayers layers = untexturedLayers(m);
  if (m.coatTexture.index < 0 && m.sheenTexture.index < 0) return layers;
  const Vec2 uv = surfaceUv(scene, hit, sp);
  if (m.coatTexture.index >= 0)
    layers.coat = minf(textureChannel(lookupTexture(scene.texturePool(), m.coatTexture, uv.x, uv.y),
                                      m.coatChannel),
                       1.0f);
  if (m.sheenTexture.index >= 0)
    layers.sheen =
        min(Vec3(1.0f),
            layers.sheen * lookupTexture(scene.texturePool(), m.sheenTexture, uv.x, uv.y).rgb);
  return layers;
}

}  // namespace candela
