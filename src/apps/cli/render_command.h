// `candela render SCENE [SCENE...] [-o OUT] [--spp N] [--seed N] [--max-depth N] [--threads N]
//                 [--backend auto|cpu|cuda] [--quiet] [--stats FILE.json]
//                 [--aov depth,normal,...] [--denoise] [--frame N] [--format png|exr|pfm]
//                 [--frames A:B] [--overwrite] [--video OUT.mp4] [--fps N]`
//
// One scene without an animation block and an image file (or nothing) for -o: one image, as
// always; with --frame N, frame N of its animation block likewise. Several scenes, an animation
// block, a folder for -o (ending in '/' or existing) or any of the sequence options: a sequence of
// frames (sequence_command.h).
#pragma once

#include <memory>

#include <CLI/CLI.hpp>

#include "apps/cli/cli_options.h"
#include "apps/cli/pass_files.h"
#include "apps/denoise/oidn_denoiser.h"
#include "render/aov_layers.h"
#include "scene/scene_desc.h"

namespace candela::cli {

// Declares the subcommand and its options on `app`; parsing fills `options`.
CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions* options);

// Loads, renders and writes the image; returns the exit code. Throws CliError, SceneError,
// ImageWriteError and std::exception for main() to report.
int runRender(const RenderCommandOptions& options);

// The CPU engine the options ask for, resolved by resolveCpuEngine for scenes of at most
// `triangles` triangles and `spheres` spheres; CliError (usage) for --no-bvh with --cpu-engine
// embree.
CpuEngine chooseCpuEngine(const RenderCommandOptions& options, uint64_t triangles,
                          uint64_t spheres);

// The passes --aov asks for, in its order, and whether it asks for the camera file; CliError
// (usage) naming an unknown name.
PassFiles choosePassFiles(const RenderCommandOptions& options);

// With --denoise, Open Image Denoise, loaded; CliError (usage) saying how to install it where it
// is not found. Without, null.
std::unique_ptr<OidnDenoiser> loadDenoiser(const RenderCommandOptions& options);

// Denoises `result` (OidnDenoiser::denoise) where there is a denoiser and the render was not
// cancelled; the seconds it took, else 0.
double denoiseTimed(const OidnDenoiser* denoiser, RenderResult& result, const SceneData& scene,
                    Renderer& renderer, const RenderOptions& render);

// Command-line values win over the scene file's (spp, seed, max depth, crop); candela's own BVH
// is left out where the renderer (`backend` with `engine`) does not trace it, and what the passes
// `aovs` need laid out is (layOutForPasses).
void applyOverrides(const RenderCommandOptions& options, Backend backend, CpuEngine engine,
                    const std::vector<Aov>& aovs, SceneDesc* desc);

}  // namespace candela::cli
