// The uv pass (docs/aovs.md): the texture coordinates of each pixel's first hits, a mesh's from
// its file (kept for the pass though no material reads them), a sphere's by its mapping.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "render/aov_layers.h"
#include "render_test_util.h"
#include "scene/flatten.h"
#include "scene/mesh_layout.h"
#include "temp_dir.h"

namespace candela {
namespace {

struct UvRender {
  SceneData scene;
  ImageLayer uv;
  Vec2 at(uint32_t x, uint32_t y) const {
    const size_t i = 2 * (size_t(y) * uv.width + x);
    return {uv.pixels[i], uv.pixels[i + 1]};
  }
};

// `json` rendered with the uv pass, its meshes' uvs kept for it where `forPass` (as the command
// line and Python do when the pass is asked for).
UvRender renderUv(const std::string& json, const std::string& baseDir, bool forPass = true) {
  SceneDesc desc = parseSceneText(json, "test.json", baseDir);
  if (forPass) layOutForPasses(desc, {Aov::Uv});
  UvRender r{flattenScene(desc), ImageLayer()};
  RenderOptions options;
  options.aovs = true;
  const RenderResult result = renderCpu(r.scene.view(), options);
  r.uv = makeAovLayers(r.scene, {Aov::Uv}, result.aovs)[0];
  return r;
}

// A quad spanning [-100, 100]^2 in the plane z = 0, its corners at uvs (0, 0) to (1, 1), and its
// left and right halves split at x = 0 by a seam: two faces whose shared corners have other uvs
// in each (u = 0.5 in the left face, 0.25 in the right one). A diffuse colour reads none of them.
const char* kSeamedQuad =
    "v -100 -100 0\nv 0 -100 0\nv 100 -100 0\nv 100 100 0\nv 0 100 0\nv -100 100 0\n"
    "vt 0 0\nvt 0.5 0\nvt 0.5 1\nvt 0 1\nvt 0.25 0\nvt 1 0\nvt 1 1\nvt 0.25 1\n"
    "f 1/1 2/2 5/3 6/4\nf 2/5 3/6 4/7 5/8\n";

// The quad 7.5 before the default camera: through each pixel centre the uv its face's corners
// give the point there, an affine function of the point on each half.
TEST(UvPass, AMeshsUvsAreItsFilesThroughEachPixelThoughNoMaterialReadsThem) {
  test::TempDir dir;
  dir.write("quad.obj", kSeamedQuad);
  const char* json = R"({
    "camera": {"width": 20, "height": 10, "fov": 90, "spp": 2},
    "render": {"antialiasing": false},
    "objects": [{"file": "quad.obj", "position": [0, 0, -7.5], "color": 0.5}],
    "lights": [{"position": [0, 0, 0], "intensity": 100}]
  })";
  const UvRender r = renderUv(json, dir.path());
  const float d = 7.5f, f = 10.0f;  // fov 90: fx = fy = width / 2
  for (uint32_t y = 0; y < 10; ++y)
    for (uint32_t x = 0; x < 20; ++x) {
      const float px = d * (x + 0.5f - 10.0f) / f, py = -d * (y + 0.5f - 5.0f) / f;
      const float u = px < 0 ? 0.5f * (px + 100) / 100 : 0.25f + 0.75f * px / 100;
      const Vec2 uv = r.at(x, y);
      EXPECT_NEAR(uv.x, u, 1e-5f) << x << "," << y;
      EXPECT_NEAR(uv.y, (py + 100) / 200, 1e-5f) << x << "," << y;
    }
  // The seam splits the two middle vertices for the pass; without it the mesh keeps its six
  // vertices and no uvs, and the pass shows (0, 0).
  EXPECT_EQ(r.scene.positions.size(), 8u);
  const UvRender plain = renderUv(json, dir.path(), false);
  EXPECT_EQ(plain.scene.positions.size(), 6u);
  EXPECT_TRUE(plain.scene.uvs.empty());
  EXPECT_EQ(plain.at(3, 3).x, 0.0f);
}

// A unit sphere seen from +x: at the image centre the point (1, 0, 0), u = 0.75 and v = 0.5 by
// the sphere's mapping (geometry/surface_uv.h); off the centre the mapping of the point the
// pixel's ray meets; the corners see nothing: (0, 0), as the position pass does.
TEST(UvPass, ASpheresUvsFollowItsMapping) {
  const uint32_t size = 15;
  const double fov = 30, distance = 5;
  const UvRender r = renderUv(R"({
    "camera": {"width": 15, "height": 15, "fov": 30, "spp": 2, "position": [5, 0, 0],
               "look_at": [0, 0, 0]},
    "render": {"antialiasing": false},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}]
  })",
                              ".");
  for (uint32_t y : {3u, 7u, 9u})
    for (uint32_t x : {4u, 7u, 10u}) {
      const std::array<double, 3> d =
          test::sphereHitSeenFromPlusX(size, size, fov, distance, 1.0, x, y);
      const double u = 0.5 + std::atan2(d[0], -d[2]) / (2.0 * 3.14159265358979323846);
      const double v = 1.0 - std::acos(d[1]) / 3.14159265358979323846;
      EXPECT_NEAR(r.at(x, y).x, u, 2e-4) << x << "," << y;
      EXPECT_NEAR(r.at(x, y).y, v, 2e-4) << x << "," << y;
    }
  EXPECT_NEAR(r.at(7, 7).x, 0.75f, 1e-4f);
  EXPECT_NEAR(r.at(7, 7).y, 0.5f, 1e-4f);
  EXPECT_EQ(r.at(0, 0).x, 0.0f);
  EXPECT_EQ(r.at(0, 0).y, 0.0f);
}

// The flow pass places a moving mesh's vertices in the next frame as the frame flattened lays
// them out: with the uv pass, split at the seams though the next frame's object (without the
// pass's mark) would not split them.
TEST(UvPass, TheNextFramesVerticesAreLaidOutAsTheFlattenedFrames) {
  test::TempDir dir;
  dir.write("quad.obj", kSeamedQuad);
  SceneDesc desc = parseSceneText(R"({"camera": {},
    "objects": [{"file": "quad.obj", "color": 0.5}]})",
                                  "test.json", dir.path());
  const SceneDesc next = desc;
  layOutForPasses(desc, {Aov::Uv});
  EXPECT_EQ(placedVertices(next.objects[0], desc.objects[0]).size(),
            flattenScene(desc).positions.size());
  EXPECT_EQ(placedVertices(next.objects[0], next.objects[0]).size(), 6u);
}

}  // namespace
}  // namespace candela
