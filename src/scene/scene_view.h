// SceneView: the flat, trivially copyable scene that the integrator sees.
//
// Arrays of plain structs + counts + indices; every name was resolved at load time. On the CPU
// the pointers point into host memory (SceneData owns it), on CUDA into device buffers.
//
// Conventions:
// - World space is right-handed, +y up. Mesh vertices are already transformed to world space.
// - `normals` is empty or parallel to `positions`: normals[i] is vertex i's shading normal,
//   octahedrally encoded (core/oct_normal.h); "none" makes a triangle with such a vertex use its
//   face normal.
// - Primitive index p in [0, sphereCount) is spheres[p]; p >= sphereCount is triangle
//   p - sphereCount. The BVH leaves index `primIndices`, which hold such primitive indices.
// - Sphere lights also appear as spheres whose material is emissive with `lightIndex` set, so
//   BSDF-sampled rays find them and weight them by multiple importance sampling.
// - Camera space follows OpenCV: +x right, +y down, +z forward.
#pragma once

#include <cstdint>
#include <type_traits>

#include "core/mat3.h"
#include "core/oct_normal.h"
#include "core/vec3.h"

namespace candela {

enum class MaterialType : uint32_t { Diffuse = 0, Mirror = 1, Glass = 2, Emissive = 3 };

struct Material {
  MaterialType type = MaterialType::Diffuse;
  Vec3 color{0.8f};     // diffuse albedo, mirror tint or glass transmission tint
  float ior = 1.5f;     // glass: relative index, outside -> inside
  Vec3 radiance{0.0f};  // emissive: emitted radiance from the front side
  int32_t lightIndex = -1;  // emissive spheres that are sphere lights: index into lights
};

struct Sphere {
  Vec3 center;
  float radius = 1;
  uint32_t material = 0;
};

// Vertex indices into positions (and into normals, which when present run parallel to
// positions). The face's outside is the side of (v1-v0)x(v2-v0) (counter-clockwise seen from
// outside). 16 bytes: the renderer's triangles stay small.
struct Triangle {
  uint32_t v[3];
  uint32_t material;
};
static_assert(sizeof(Triangle) == 16, "Triangle must stay 16 bytes");

enum class LightType : uint32_t { Point = 0, Sphere = 1 };

struct Light {
  LightType type = LightType::Point;
  Vec3 position;
  float radius = 0;   // sphere lights
  Vec3 power;         // point: total power (color * intensity)
  Vec3 radiance;      // sphere: uniform outgoing radiance color*intensity/(4 pi^2 r^2)
  uint32_t sphere = 0;  // sphere lights: their index in SceneView::spheres
  // The probability that next-event estimation samples this light at a shading point: 1 when
  // the scene has at most kSampleEveryLightUpTo lights (each gets its own shadow ray), else one
  // light is picked in proportion to power. selectCdf is the running sum of the picking
  // probabilities up to and including this light, 1 from the last light with any power on.
  float selectPmf = 0;
  float selectCdf = 0;
};

// Up to this many lights every shading point samples each of them: on the bench scenes (two and
// three point lights) that reaches a given error in 25-45% less time than picking one light by
// power, whose extra noise outweighs the shadow rays it saves. Beyond it the cost per shading
// point would grow with the light count, and one light is picked.
constexpr uint32_t kSampleEveryLightUpTo = 8;

// Node of the 4-wide BVH the renderer traverses, 128 bytes (two cache lines). It holds the boxes
// of up to four children side by side, one array per axis, so that one visit tests four boxes
// in a loop the compiler turns into vector instructions. nodes[0] is the root.
// Child slot i: count[i] == 0 and child[i] a node index for an inner child; count[i] > 0 for a
// leaf of count[i] primitives from primIndices[child[i]]; an unused slot has an empty box
// (lo = +inf, hi = -inf), which no ray hits, and count 0, child kNoBvhChild.
struct BvhNode {
  float lo[3][4];  // [axis][child]
  float hi[3][4];
  uint32_t child[4];
  uint8_t count[4];
  uint32_t pad[3];
};
static_assert(sizeof(BvhNode) == 128, "BvhNode must stay 128 bytes");
constexpr uint32_t kNoBvhChild = 0xffffffffu;

struct Camera {
  uint32_t width = 512, height = 512;
  Mat3 inverseK;         // pixel (u, v, 1) -> camera-space direction with z = 1
  Mat3 cameraToWorld;    // OpenCV camera axes -> world
  Vec3 position;         // camera centre in world space
  float apertureRadius = 0;
  float focusDistance = 1;  // along camera +z
};

enum class IntegratorType : uint32_t { Path = 0, Direct = 1 };

struct RenderSettings {
  uint32_t spp = 64;
  uint32_t maxDepth = 8;
  IntegratorType integrator = IntegratorType::Path;
  bool antialiasing = true;
  uint64_t seed = 0;
  // false: test every primitive for every ray instead of traversing the BVH. Only for
  // benchmarks that measure what the BVH buys (the seed's "bounding box" comparison).
  bool useBvh = true;
};

struct SceneView {
  const Material* materials = nullptr;
  const Sphere* spheres = nullptr;
  const Vec3* positions = nullptr;
  const OctNormal* normals = nullptr;
  const Triangle* triangles = nullptr;
  const Light* lights = nullptr;
  const BvhNode* nodes = nullptr;
  const uint32_t* primIndices = nullptr;

  uint32_t materialCount = 0, sphereCount = 0, positionCount = 0, normalCount = 0;
  uint32_t triangleCount = 0, lightCount = 0, nodeCount = 0;

  Vec3 environment{0.0f};
  // Whether a scattered ray can find any light: an emissive material (sphere lights included) or
  // a nonzero environment. Without, light arrives only by shadow rays to point lights, and the
  // ray a path would scatter from its last interaction is not traced: it could add nothing.
  bool emissionReachable = true;
  Camera camera;
  RenderSettings settings;

  CANDELA_HDI uint32_t primitiveCount() const { return sphereCount + triangleCount; }
};
static_assert(std::is_trivially_copyable<SceneView>::value, "SceneView must be trivially copyable");

}  // namespace candela
