// `candela render` for sequences: several scene files (one frame each, in order), one scene with
// an animation block, or one still written as a one-frame sequence into a folder.
//
// Every scene is loaded and validated before anything renders, so a bad file in the middle of a
// sequence is reported (with its name, exit 2) and nothing is written. Frame i uses the seed
// render.seed + i and is written atomically to DIR/frame_0000.png ...; frames that exist are
// skipped unless --overwrite, so an interrupted run resumes where it stopped. `--frames A:B`
// renders frames A to B-1 (the end is exclusive, as in Python). With --video the frames are then
// encoded by ffmpeg.
#pragma once

#include <vector>

#include "apps/cli/cli_options.h"
#include "scene/scene_desc.h"

namespace candela::cli {

// Renders the sequence of already loaded, validated `scenes` (one scene with an animation block,
// or stills); returns the exit code. Throws CliError, SceneError and ImageWriteError.
int runSequence(const RenderCommandOptions& options, std::vector<SceneDesc> scenes);

}  // namespace candela::cli
