// SceneView: the flat, trivially copyable scene that the integrator sees.
//
// The geometry (geometry/geometry_view.h) plus what shades it: materials, lights, environment,
// camera and settings. Arrays of plain structs + counts + indices; every name was resolved at
// load time. On the CPU the pointers point into host memory (SceneData owns it), on CUDA into
// device buffers.
#pragma once

#include <type_traits>

#include "core/vec3.h"
#include "geometry/geometry_view.h"
#include "render/camera.h"
#include "render/camera_motion.h"
#include "render/environment.h"
#include "render/light.h"
#include "render/light_motion.h"
#include "render/light_tree.h"
#include "render/material.h"
#include "render/motion.h"
#include "render/render_settings.h"

namespace candela {

// The arrays that shade the geometry, in the form of CANDELA_GEOMETRY_ARRAYS; the light tree and
// the environment map's arrays are rewritten with their own contents only.
// lightTree is the light tree over the lights other than the environment (render/light_tree.h;
// empty when every light is sampled or none but the environment has power). envTexels is the
// environment map (width x height, rows from the top; empty for a constant environment), and
// envConditionalCdf/envMarginalCdf with their guide tables and the weights at its cells' corners
// (envCellCorners) its sampling distribution (core/distribution2d.h). materialMotions, parallel
// to materials, is the motion of each material's instance to the next frame; only renders with
// the flow pass have it. flowVertices, empty or parallel to positions, holds where each vertex of a
// mesh that moves apart (InstanceMotion::perVertex) stands in the next frame. backwardMotions and
// backwardFlowVertices are the same towards the previous frame, for the backward flow pass.
// lightPathOrder lists the lights in the order their light-subpath picks are laid out over
// [0, 1) (render/light_path.h, pickLightPathLight). infiniteLights lists the lights at infinity
// that next-event estimation picks, each in a share of its own (render/light_selection.h).
// plasticCoats holds the coat tables of the plastics and clear coats whose roughness is textured
// (render/bsdf_plastic.h, Material::plasticCoatTable and coatTable); sheenTables the sheen's tables
// by roughness level where some sheen's roughness is textured (render/surface_layers.h), else
// nothing. vertexColors is empty or parallel to
// positions: the linear colour that tints a mesh vertex's materials (1 for vertices without).
// objectCoordinates is empty or parallel to positions: each vertex's place in its object's frame,
// normalised to [0, 1] over the object's box, for the object_coordinates pass
// (render/object_coordinates.h).
// lightPoses holds the poses of the point lights that move while the shutter is open, each
// light's at every motionTimes from its Light::shape on (render/light_motion.h).
// cameraPoses is empty, or the camera's poses across the exposure of a motion-blurred frame
// (render/camera_motion.h), at least two.
#define CANDELA_SHADING_ARRAYS(X)                                            \
  X(Material, materials, materialCount, Values)                              \
  X(Light, lights, lightCount, Values)                                       \
  X(LightPose, lightPoses, lightPoseCount, Values)                           \
  X(LightTreeNode, lightTree, lightTreeNodeCount, LightTree)                 \
  X(Vec3, envTexels, envTexelCount, EnvironmentMap)                          \
  X(float, envConditionalCdf, envConditionalCdfCount, EnvironmentMap)        \
  X(float, envMarginalCdf, envMarginalCdfCount, EnvironmentMap)              \
  X(uint32_t, envConditionalGuide, envConditionalGuideCount, EnvironmentMap) \
  X(uint32_t, envMarginalGuide, envMarginalGuideCount, EnvironmentMap)       \
  X(float, envCellCorners, envCellCornerCount, EnvironmentMap)               \
  X(InstanceMotion, materialMotions, materialMotionCount, Values)            \
  X(Vec3, flowVertices, flowVertexCount, Values)                             \
  X(InstanceMotion, backwardMotions, backwardMotionCount, Values)            \
  X(Vec3, backwardFlowVertices, backwardFlowVertexCount, Values)             \
  X(uint32_t, lightPathOrder, lightPathOrderCount, Values)                   \
  X(uint32_t, infiniteLights, infiniteLightCount, Values)                    \
  X(float, plasticCoats, plasticCoatCount, Values)                           \
  X(float, sheenTables, sheenTableCount, Values)                             \
  X(Vec3, vertexColors, vertexColorCount, Structure)                         \
  X(Vec3, objectCoordinates, objectCoordinateCount, Structure)               \
  X(CameraPose, cameraPoses, cameraPoseCount, Values)

// Every array of the kernel's scene: SceneData, SceneData::view and the CUDA upload expand
// this.
#define CANDELA_SCENE_ARRAYS(X) CANDELA_GEOMETRY_ARRAYS(X) CANDELA_SHADING_ARRAYS(X)

struct SceneView : GeometryView {
  CANDELA_SHADING_ARRAYS(CANDELA_VIEW_ARRAY_FIELDS)

  uint32_t firstTriangleLight = 0;  // lights from here on are triangles (see lightOfPrimitive)
  // Whether the scene's one light is a point light, which next-event estimation samples without
  // a pick (render/light.h, isLoneDeltaLight).
  bool loneDeltaLight = false;
  // How many point lights a path's first interaction samples each of (render/light.h,
  // firstHitDeltaLights); 0: one light is picked there too.
  uint32_t firstHitDeltaLights = 0;
  // How many lights next-event estimation picks, each with its own shadow ray, at a path's
  // first interaction (RenderSettings::firstHitLightSamples, resolved): more than one only where
  // a light is picked there (takesFirstHitLightSamples).
  uint32_t firstHitLightSamples = 1;
  // How many lights start light subpaths (render/light_path.h): those with power but the lights
  // at infinity, where the integrator is "path" and a path may have two interactions; 0 for
  // none. Where some of them have a surface, each subpath draws two numbers for its point.
  uint32_t lightPathLights = 0;
  bool areaLightPaths = false;
  // A camera path's interactions up to this depth are connected to the light vertex
  // (RenderSettings::lightPathDepth, resolved: "auto" as kEveryInteraction).
  uint32_t lightPathDepth = UINT32_MAX;
  // Paths follow both lobes of smooth glass at interactions up to this depth (0: at none), the
  // reflection as a branch (render/path_branch.h).
  uint32_t glassSplitDepth = 0;
  // The share of the picks that goes to each of infiniteLights; the light tree has the rest.
  float infiniteLightShare = 0.0f;
  // Whether some of infiniteLights is a directional light with a disc, which the rays that leave
  // the scene may see (render/light.h, hasSunDisc).
  bool sunDiscs = false;
  // Whether a material is glass of index 1 (render/index_matched.h), whose media shadow rays cross
  // (render/shadow_transmittance.h); such scenes start no light subpaths.
  bool indexMatchedMedia = false;
  Environment environment;
  // Whether a scattered ray can find any light: an emissive material (sphere lights included), a
  // nonzero environment or a sun's disc. Without, light arrives only by shadow rays to point
  // lights, and the ray a path would scatter from its last interaction is not traced: it could add
  // nothing.
  bool emissionReachable = true;
  // Whether some material that reflects also emits (its "emission"): a hit checks what its
  // surface emits only where one does, and an emissive material's otherwise.
  bool reflectorsEmit = false;
  Camera camera;
  RenderSettings settings;
  FlowFrames flow;          // the flow pass's cameras (render/flow.h)
  FlowFrames backwardFlow;  // the backward flow pass's: `next` is the previous frame's camera
};
static_assert(std::is_trivially_copyable<SceneView>::value, "SceneView must be trivially copyable");

// The environment's radiance along world direction `d` (unit length).
CANDELA_HDI_ALWAYS Vec3 environmentRadiance(const SceneView& scene, const Vec3& d) {
  const Environment& e = scene.environment;
  if (e.width == 0) return e.radiance;
  float u, v;
  directionToMap(e.fromWorld * d, &u, &v);
  return e.radiance * lookupMap(scene.envTexels, e.width, e.height, u, v);
}

// The environment map's sampling distribution.
CANDELA_HDI Distribution2D environmentDistribution(const SceneView& scene) {
  return {scene.envConditionalCdf, scene.envMarginalCdf,           scene.envConditionalGuide,
          scene.envMarginalGuide,  scene.environment.grid.columns, scene.environment.grid.rows,
          scene.envCellCorners};
}

}  // namespace candela
