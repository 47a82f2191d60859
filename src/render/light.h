// Lights that next-event estimation samples: point and directional lights, the environment and
// the emitting surfaces of the scene.
//
// Every emitter is a light. A point light (or a spot light, a point light limited to a cone) and
// a directional light (one direction, from infinitely far) are declared in the scene; the
// environment, unless it is black, is a light (render/environment.h);
// every sphere and every triangle whose material is emissive (a declared sphere light included)
// is an area light whose shape is that primitive: its position and size are the primitive's, its
// radiance the material's, and the primitive names the light back (Sphere::light, or the
// triangle lights' order: see lightOfPrimitive), so BSDF-sampled rays that hit it are weighted
// by multiple importance sampling.
#pragma once

#include <cstdint>

#include "core/vec3.h"
#include "render/light_profile.h"
#include "render/spot_cone.h"

namespace candela {

enum class LightType : uint32_t {
  Point = 0,
  Sphere = 1,
  Triangle = 2,
  Environment = 3,
  Directional = 4
};

// Lights at infinity, which the light tree cannot bound: each is picked in a share of its own
// (render/light_selection.h).
CANDELA_HDI bool isInfiniteLight(LightType t) {
  return t == LightType::Environment || t == LightType::Directional;
}

// Lights outside the light tree (those at infinity, lights without power) have this trail.
constexpr uint64_t kNotInLightTree = ~uint64_t(0);

struct Light {
  LightType type = LightType::Point;
  Vec3 position;       // point lights
  // Point lights: total emitted power (color * intensity). Directional lights: the irradiance
  // of a surface facing them (color * intensity).
  Vec3 power;
  Vec3 direction;  // directional lights: the unit direction the light travels in
  // Directional lights: 1 - cos of the angular radius of the sun's disc, whose every direction
  // sends the same radiance; 0 for a delta light, of one direction.
  float sunOneMinusCos = 0.0f;
  bool hiddenFromCamera = false;  // directional lights: camera rays do not see its disc
  // Point and directional lights: whether it moves while the shutter is open, its poses then from
  // SceneView::lightPoses[shape] on (render/light_motion.h).
  bool moves = false;
  // Named, so that no byte of a light is left unset (frames compare lights byte by byte).
  uint8_t padding[2] = {};
  // A spot light is a point light limited to a cone; its power is the point light's it would be
  // without one (its intensity within the beam is that light's).
  SpotCone spot;
  // Area lights: index into the scene's spheres or triangles, by type; a point or directional light
  // that moves: its first pose in SceneView::lightPoses.
  uint32_t shape = 0;
  // The light's path in the light tree (render/light_tree.h): its slot at each level, 3 bits
  // a level from the lowest, the root's first.
  uint64_t trail = kNotInLightTree;
  // The chance that a sample's light subpath starts here (render/light_path.h), by power (0 for
  // the lights at infinity, which start none), and the sum of those chances up to this light in
  // SceneView::lightPathOrder (1 from the last light with a chance on).
  float pathPmf = 0.0f, pathCdf = 0.0f;
  // A light with a surface: pathPmf times the density by area of a subpath's point on it
  // (render/light_emission.h, emissionAreaPdf); 0 for the others.
  float pathAreaPdf = 0.0f;
  // A point or spot light's intensity by direction, from an IES file (render/light_profile.h).
  LightProfile profile;
};

// Whether light `l` lights from one point or along one direction, which no scattered ray finds:
// only next-event estimation (and light subpaths) reach it, and its sample draws no numbers.
CANDELA_HDI bool isDeltaLight(const Light& l) {
  return l.type == LightType::Point ||
         (l.type == LightType::Directional && l.sunOneMinusCos == 0.0f);
}

// Whether light `l` is a directional light with a disc, which rays that leave the scene may see.
CANDELA_HDI bool hasSunDisc(const Light& l) {
  return l.type == LightType::Directional && l.sunOneMinusCos > 0.0f;
}

// Whether samples' light subpaths start at light `l` (render/light_path.h), where the render
// traces them (connectsLightSubpaths, which decides the light's MIS heuristic).
CANDELA_HDI bool startsLightSubpaths(const Light& l) { return l.pathPmf > 0.0f; }

// Whether the `count` lights are one point or directional light, which next-event estimation
// then samples at every shading point: there is nothing to pick, and a pick would cost a tree
// walk and a random number. Every other scene picks one light per shading point: each light at
// infinity in a share of its own, the rest from the light tree (render/light_selection.h).
// Sampling each of up to 8 point lights, each with its own shadow ray, won while the pick went by
// power alone; the tree also weighs distance and orientation, and picking now wins or ties
// (Sponza's three lamps: 0.8x the render time for 3% more error; the dragon's two: even;
// docs/performance.md).
inline bool isLoneDeltaLight(const Light* lights, size_t count) {
  return count == 1 && isDeltaLight(lights[0]);
}

// Scenes of at most this many lights, all of them point or directional lights, sample each of them
// at a path's first interaction, each with its own shadow ray (docs/performance.md, Denoising):
// shadow rays towards so few lights go as packets (render/render_pixel.h).
constexpr uint32_t kEachDeltaLightUpTo = 4;

// How many delta lights next-event estimation samples each of at a path's first interaction: the
// `count` lights where there are 2 to kEachDeltaLightUpTo of them and all are delta lights, else
// 0 (one light picked, as at every later interaction). The pick's noise at the first interaction
// is what the image shows sharpest: a pixel's samples split between the lights in whole numbers,
// so its direct light differs from its neighbours' by that rounding, which a denoiser smooths
// away with the detail (docs/performance.md, Denoising: the dragon's denoised error 13-15% lower).
inline uint32_t firstHitDeltaLights(const Light* lights, size_t count) {
  if (count < 2 || count > kEachDeltaLightUpTo) return 0;
  for (size_t i = 0; i < count; ++i)
    if (!isDeltaLight(lights[i])) return 0;
  return uint32_t(count);
}

}  // namespace candela
