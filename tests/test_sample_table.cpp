// The CPU's sample tables (core/sample_table.h, backends/cpu/sample_table_fill.h): a stream that
// reads its numbers from a packet's table draws exactly, bit for bit, what it draws alone, in any
// order of the lanes' requests, where lanes draw a dimension in different ways, past the table's
// dimensions and on branches.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "backends/cpu/sample_table_fill.h"
#include "core/rng.h"
#include "core/sobol_sampler.h"
#include "geometry/bvh_tracer.h"
#include "render/render_pixel.h"
#include "render_test_util.h"

namespace candela {
namespace {

uint32_t bitsOf(float f) {
  uint32_t b;
  std::memcpy(&b, &f, sizeof b);
  return b;
}

// What request `step` of lane `lane` is: mostly the same for every lane (paths that do the same
// things), now and then another for some lanes (a path that chose otherwise, or ended).
enum class Draw { kOneD, kTwoD, kSkip };
Draw drawAt(uint32_t step, uint32_t lane) {
  const uint64_t h = mix64(step * 0x9e3779b97f4a7c15ull + 17);
  Draw d = h % 3 == 0 ? Draw::kOneD : Draw::kTwoD;
  if (h % 7 == 3) d = Draw::kSkip;
  if ((mix64(h ^ lane) & 7) == 0) d = d == Draw::kTwoD ? Draw::kOneD : Draw::kTwoD;
  return d;
}

// Makes lane's request `step` of both streams and expects the same bits.
void drawBoth(SampleStream& tabled, SampleStream& alone, uint32_t step, uint32_t lane) {
  switch (drawAt(step, lane)) {
    case Draw::kOneD:
      ASSERT_EQ(bitsOf(tabled.next1D()), bitsOf(alone.next1D())) << "step " << step;
      break;
    case Draw::kTwoD: {
      float u1, v1, u2, v2;
      tabled.next2D(&u1, &v1);
      alone.next2D(&u2, &v2);
      ASSERT_EQ(bitsOf(u1), bitsOf(u2)) << "step " << step;
      ASSERT_EQ(bitsOf(v1), bitsOf(v2)) << "step " << step;
      break;
    }
    case Draw::kSkip:
      tabled.skip();
      alone.skip();
      break;
  }
}

class SampleTables : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!sampleTableFill()) GTEST_SKIP() << "this CPU has no sample tables (they need AVX2)";
  }
};

TEST_F(SampleTables, StreamsDrawWhatTheyDrawAloneInAnyOrder) {
  const uint32_t steps = SampleTable::kMaxDimensions + 12;  // past the table too
  SampleTable table;
  table.fill = sampleTableFill();
  // Up to 65,536 spp the fill walks its permutations in 16-bit lanes, above in 32-bit ones.
  for (uint32_t spp : {1u, 3u, 8u, 16u, 24u, 100u, 1000u, 65536u, 65537u, 131072u}) {
    std::vector<uint32_t> firsts;  // every packet of a small spp; the first, a middle, the last
    for (uint32_t first = 0; first < spp; first += SampleTable::kLanes)
      if (spp <= 128 || first == 0 || first == spp / 32 * 16 || first + SampleTable::kLanes >= spp)
        firsts.push_back(first);
    for (uint64_t seed : {0ull, 7ull}) {
      for (uint64_t pixel : {0ull, 12345ull}) {
        for (uint32_t first : firsts) {
          const uint32_t lanes = std::min(SampleTable::kLanes, spp - first);
          for (bool laneByLane : {false, true}) {
            SCOPED_TRACE(::testing::Message()
                         << "spp " << spp << " seed " << seed << " pixel " << pixel << " first "
                         << first << (laneByLane ? " lane by lane" : " in step"));
            table.start(samplePixelKey(seed, pixel), first, lanes, spp);
            std::vector<SampleStream> tabled, alone;
            for (uint32_t k = 0; k < lanes; ++k) {
              tabled.emplace_back(seed, pixel, first + k, spp, &table, k);
              alone.emplace_back(seed, pixel, first + k, spp);
            }
            if (laneByLane) {
              for (uint32_t k = 0; k < lanes; ++k)
                for (uint32_t step = 0; step < steps; ++step)
                  drawBoth(tabled[k], alone[k], step, k);
            } else {
              for (uint32_t step = 0; step < steps; ++step)
                for (uint32_t k = 0; k < lanes; ++k) drawBoth(tabled[k], alone[k], step, k);
            }
          }
        }
      }
    }
  }
}

// A branch (render/path_branch.h) draws far past the table; the stream it left goes on in it.
TEST_F(SampleTables, BranchesAndTheStreamsTheyLeaveDrawWhatTheyDrawAlone) {
  SampleTable table;
  table.fill = sampleTableFill();
  table.start(samplePixelKey(3, 99), 0, SampleTable::kLanes, 16);
  for (uint32_t k = 0; k < SampleTable::kLanes; ++k) {
    SampleStream tabled(3, 99, k, 16, &table, k), alone(3, 99, k, 16);
    for (uint32_t step = 0; step < 5; ++step) drawBoth(tabled, alone, step, k);
    SampleStream tabledBranch = tabled.branch(), aloneBranch = alone.branch();
    for (uint32_t step = 5; step < 15; ++step) {
      drawBoth(tabledBranch, aloneBranch, step, k);
      drawBoth(tabled, alone, step, k);
    }
  }
}

// Answers a packet's queries ray by ray, so that renderPixelSamples takes its packet path.
struct PacketsRayByRay : BvhTracer {
  static constexpr uint32_t kPacketWidth = 16;
  void closestPacket(const Ray* rays, uint32_t n, Hit* hits) const {
    for (uint32_t i = 0; i < n; ++i) {
      hits[i] = Hit();
      closest(rays[i], &hits[i]);
    }
  }
  void occludedPacket(const Ray* rays, const uint32_t* skipPrims, uint32_t n,
                      bool* blocked) const {
    for (uint32_t k = 0; k < n; ++k) blocked[k] = occluded(rays[k], skipPrims[k]);
  }
};

uint32_t fills = 0;
void countingFill(SampleTable* table, uint32_t entry, bool twoD) {
  ++fills;
  sampleTableFill()(table, entry, twoD);
}

// Renders samples [first, first + count) of pixel (x, y) with and without a table and expects the
// same radiance, bit for bit; returns how many times the table was filled.
template <class Tracer>
uint32_t fillsOfOneRange(const SceneView& view, const Tracer& tracer, uint32_t x, uint32_t y,
                         uint32_t first, uint32_t count) {
  SampleTable table;
  table.fill = countingFill;
  RayCounters counters;
  fills = 0;
  const Vec3 tabled = renderPixelSamples(view, tracer, x, y, first, count, counters, Vec3(0.0f),
                                         nullptr, &table);
  const uint32_t tableFills = fills;
  const Vec3 alone = renderPixelSamples(view, tracer, x, y, first, count, counters);
  EXPECT_EQ(bitsOf(tabled.x), bitsOf(alone.x));
  EXPECT_EQ(bitsOf(tabled.y), bitsOf(alone.y));
  EXPECT_EQ(bitsOf(tabled.z), bitsOf(alone.z));
  return tableFills;
}

// A table serves only packets (or, ray by ray, runs of samples) of at least kMinLanes samples,
// below which a fill costs more than it saves; either way a pixel's radiance is what it is
// without one.
TEST_F(SampleTables, ServeOnlyPacketsOfEightSamplesOrMore) {
  const SceneData data = test::loadTestScene(test::lampUnderTheCeiling(
      R"("width": 8, "height": 8, "spp": 24)", R"("max_depth": 5, "light_paths": "on")"));
  const SceneView view = data.view();
  const BvhTracer rayByRay{&view};
  const PacketsRayByRay packets{{&view}};
  for (uint32_t count : {1u, 3u, 7u}) {
    SCOPED_TRACE(::testing::Message() << count << " samples");
    EXPECT_EQ(fillsOfOneRange(view, rayByRay, 4, 5, 0, count), 0u);
    EXPECT_EQ(fillsOfOneRange(view, packets, 4, 5, 0, count), 0u);
    EXPECT_EQ(fillsOfOneRange(view, packets, 4, 5, 16, count), 0u);  // a spp's last packet
  }
  for (uint32_t count : {8u, 16u, 24u}) {
    SCOPED_TRACE(::testing::Message() << count << " samples");
    EXPECT_GT(fillsOfOneRange(view, rayByRay, 4, 5, 0, count), 0u);
    EXPECT_GT(fillsOfOneRange(view, packets, 4, 5, 0, count), 0u);
  }
  // 20 samples: a packet of 16 with a table and one of 4 without, as 16 alone fill it.
  EXPECT_EQ(fillsOfOneRange(view, packets, 4, 5, 0, 20),
            fillsOfOneRange(view, packets, 4, 5, 0, 16));
}

}  // namespace
}  // namespace candela
