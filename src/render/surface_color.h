// The colour of a material at a surface point: `color` alone, or its texture times `color` (a
// tint, 1 unless the scene or the MTL's Kd sets another), times the mesh's vertex colours where
// it has them; likewise an emitter's radiance (which vertex colours leave), and the roughness,
// which a texture replaces.
#pragma once

#include "core/texture.h"
#include "geometry/surface.h"
#include "geometry/surface_uv.h"
#include "render/material.h"
#include "render/scene_view.h"
#include "render/vertex_color.h"

namespace candela {

// The colour of a field that may be a texture: `tint`, or texture `ref`'s colour at the point
// times it.
CANDELA_HDI Vec3 surfaceTintedColour(const SceneView& scene, const Vec3& tint,
                                     const TextureRef& ref, const Hit& hit,
                                     const SurfacePoint& sp) {
  if (ref.index < 0) return tint;
  const Vec2 uv = surfaceUv(scene, hit, sp);
  return tint * lookupTexture(scene.texturePool(), ref, uv.x, uv.y).rgb;
}

CANDELA_HDI Vec3 surfaceColor(const SceneView& scene, const Material& m, const Hit& hit,
                              const SurfacePoint& sp) {
  return surfaceTintedColour(scene, m.color * vertexColor(scene, hit), m.colorTexture, hit, sp);
}

// The transmittance of a translucent material m at the point (vertex colours tint the reflected
// colour alone).
CANDELA_HDI Vec3 surfaceTransmittance(const SceneView& scene, const Material& m, const Hit& hit,
                                      const SurfacePoint& sp) {
  return surfaceTintedColour(scene, m.transmittance, m.transmittanceTexture, hit, sp);
}

// The value in [0, 1] of a field that may be a texture: `constant`, or texture `ref`'s luminance
// or chosen channel at the point (at most 1).
CANDELA_HDI float surfaceUnitValue(const SceneView& scene, float constant, const TextureRef& ref,
                                   uint32_t channel, const Hit& hit, const SurfacePoint& sp) {
  if (ref.index < 0) return constant;
  const Vec2 uv = surfaceUv(scene, hit, sp);
  return minf(textureChannel(lookupTexture(scene.texturePool(), ref, uv.x, uv.y), channel), 1.0f);
}

// The roughness of m at the point: `roughness`, or its texture's value there.
CANDELA_HDI float surfaceRoughness(const SceneView& scene, const Material& m, const Hit& hit,
                                   const SurfacePoint& sp) {
  return surfaceUnitValue(scene, m.roughness, m.roughnessTexture, m.roughnessChannel, hit, sp);
}

// The radiance an emissive material with an emission texture emits at texture coordinates uv.
CANDELA_HDI Vec3 texturedRadiance(const SceneView& scene, const Material& m, const Vec2& uv) {
  return m.radiance * lookupTexture(scene.texturePool(), m.emissionTexture, uv.x, uv.y).rgb;
}

// The radiance of emissive triangle `tri` at barycentrics (b1, b2); UVs only for a texture.
CANDELA_HDI Vec3 triangleRadiance(const SceneView& scene, const Material& m, const Triangle& tri,
                                  float b1, float b2) {
  if (m.emissionTexture.index < 0) return m.radiance;
  return texturedRadiance(scene, m, triangleUv(scene, tri, b1, b2));
}

// The radiance of emissive sphere s, of material m, at point p of its surface (whose direction
// from the centre only a texture needs).
CANDELA_HDI Vec3 sphereRadiance(const SceneView& scene, const Material& m, const Sphere& s,
                                const Vec3& p) {
  if (m.emissionTexture.index < 0) return m.radiance;
  return texturedRadiance(scene, m, sphereUv(normalize(p - s.center)));
}

CANDELA_HDI Vec3 surfaceRadiance(const SceneView& scene, const Material& m, const Hit& hit,
                                 const SurfacePoint& sp) {
  if (m.emissionTexture.index < 0) return m.radiance;
  return texturedRadiance(scene, m, surfaceUv(scene, hit, sp));
}

}  // namespace candela
