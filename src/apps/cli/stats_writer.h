// `candela render --stats FILE.json`: the measured figures of one still render, as a small JSON
// object that the benchmark suite (bench/run) reads. Written by hand (no JSON library in the CLI).
//
// Keys (seconds are wall time; bytes are the host arrays' sizes, capacity excluded):
//   scene, backend, threads, width, height, spp, max_depth, integrator, antialiasing, use_bvh,
//   load_seconds       reading and validating the scene file (meshes included)
//   flatten_seconds    flattenScene: meshes to world space (+ candela's own BVH build)
//   engine             the ray engine: "bvh" (candela's own) or "embree" (the CPU's, when built)
//   cpu_isa            the instruction set of the CPU backend's render loop: "x86-64" or
//                      "x86-64-v4" (backends/cpu/tile_renderer.h); "" on the GPU
//   bvh_build_seconds  the engine's BVH build alone (SceneData::bvh.buildSeconds, or Embree's)
//   bvh_mtris_per_second  triangles / bvh_build_seconds / 1e6
//   triangles, spheres, bvh_nodes, bvh_leaves, bvh_max_depth (the own BVH's; 0 with Embree)
//   memory_bytes {nodes, prim_indices, positions, normals, triangles, engine, total}; engine:
//                      what Embree holds (its BVH; it shares the scene's vertices)
//   bytes_per_triangle  memory_bytes.total / triangles (0 without triangles)
//   light_paths {setting, on, piloted, pilot_seconds, pilot_rays, pilot_with, pilot_without,
//                depth_setting, depth, depth_piloted, pilot_every_interaction,
//                pilot_first_interactions}:
//                      whether samples started light subpaths (backends/render_pilot.h);
//                      pilot_with and pilot_without are the pilot's variance x cost of either;
//                      depth the deepest interaction joined to them ("all" or a number), and
//                      the pilot's two figures for it (every interaction, the first two)
//   first_hit_light_samples {setting, count, piloted, pilot_one, pilot_two}
//   render_seconds, samples, samples_per_second (render_seconds includes pilot_seconds; rays
//                      and rays_per_second count the image's rays alone)
//   rays {camera, bounce, shadow, total}, rays_per_second
//   denoise_seconds    --denoise: the denoiser (emitters seen sampled again, the filters); else 0
//   peak_rss_bytes     getrusage(RUSAGE_SELF).ru_maxrss, in bytes
#pragma once

#include <string>

#include "backends/render_pilot.h"
#include "backends/renderer.h"
#include "render/render_result.h"
#include "render/scene_data.h"

namespace candela::cli {

struct RenderStats {
  std::string scene;
  std::string backend;
  int threads = 0;
  bool useBvh = true;  // false under --no-bvh (the one-level tree of the benchmarks)
  double loadSeconds = 0;
  double flattenSeconds = 0;
  double denoiseSeconds = 0;
  AccelerationStats acceleration;  // the renderer's ray engine
  PilotChoice pilot;  // what its pilot chose: light subpaths, the first interaction's light samples
};

// The JSON text (one object, trailing newline).
std::string renderStatsJson(const RenderStats& info, const SceneData& scene,
                            const RenderResult& result);

// Peak resident set size of this process so far, in bytes.
long long peakRssBytes();

}  // namespace candela::cli
