// The CPU render threads flush denormals (backends/cpu/flush_denormals.h), and give the caller's
// thread back its own floating-point mode.
#include <gtest/gtest.h>

#include <string>

#include "backends/cpu/flush_denormals.h"
#include "render_test_util.h"

namespace candela {
namespace {

#if CANDELA_FLUSH_DENORMALS
// MXCSR's control bits: its low six are sticky exception flags that any arithmetic may raise.
unsigned floatingPointMode() { return _mm_getcsr() & ~0x3fu; }
#endif

// A product whose exact value is denormal (1e-40), computed at run time.
float denormalProduct() {
  volatile float a = 1e-30f, b = 1e-10f;
  return a * b;
}

TEST(FlushDenormals, FlushesWhileAliveAndRestoresTheModeAfter) {
#if !CANDELA_FLUSH_DENORMALS
  GTEST_SKIP() << "no SSE on this CPU: denormals are left as they are";
#else
  ASSERT_GT(denormalProduct(), 0.0f) << "the test thread must start without flushing";
  const unsigned before = floatingPointMode();
  {
    const FlushDenormals flush;
    EXPECT_EQ(denormalProduct(), 0.0f);
  }
  EXPECT_EQ(floatingPointMode(), before);
  EXPECT_GT(denormalProduct(), 0.0f);
#endif
}

// A sphere lit by a point light of `intensity`, 8x8 pixels: the centre pixel sees it.
RenderResult renderLitSphere(const std::string& intensity, int threads = 0) {
  return test::renderTestScene(R"({
    "camera": {"width": 8, "height": 8, "fov": 40, "position": [0, 0, 5], "look_at": [0, 0, 0],
               "spp": 2},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [3, 3, 3], "intensity": )" +
                                   intensity + "}]}",
                               threads);
}
constexpr size_t kCentre = (4 * 8 + 4) * 3;

TEST(FlushDenormals, RenderGivesTheCallersThreadItsModeBack) {
#if !CANDELA_FLUSH_DENORMALS
  GTEST_SKIP() << "no SSE on this CPU: denormals are left as they are";
#else
  const unsigned before = floatingPointMode();
  // One thread: the tiles are rendered on this one.
  EXPECT_GT(renderLitSphere("100", 1).image.pixels[kCentre], 0.0f) << "the sphere is lit";
  EXPECT_EQ(floatingPointMode(), before);
  EXPECT_GT(denormalProduct(), 0.0f);
#endif
}

// What a light too faint for float's normal range (below 1.2e-38) gives is flushed to zero on
// the render threads: the light's own intensity reads as zero there.
TEST(FlushDenormals, RenderThreadsFlushDenormals) {
#if !CANDELA_FLUSH_DENORMALS
  GTEST_SKIP() << "no SSE on this CPU: denormals are left as they are";
#else
  EXPECT_GT(renderLitSphere("1e-30").image.pixels[kCentre], 0.0f) << "faint, in the normal range";
  for (float v : renderLitSphere("1e-39").image.pixels) EXPECT_EQ(v, 0.0f);
#endif
}

}  // namespace
}  // namespace candela
