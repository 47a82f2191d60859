// Where a render writes, checked before anything renders: no output may replace a file the render
// reads (a scene file, a mesh, a material library, an environment map, a texture) or another output, and
// each must be a file whose folder exists or can be made, and can be written in. Paths are
// compared as the files they name: "./a.json", "x/../a.json", a link to a.json and a.json are
// all one file.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace candela::cli {

struct InputFile {
  std::string path;
  const char* kind;  // "the scene file", "the mesh", ...
};

struct OutputFile {
  std::string option;  // as given on the command line: "-o", "--stats", "--video"
  std::string path;
};

// Every file the scenes read.
std::vector<InputFile> inputFiles(const std::vector<SceneDesc>& scenes);

// Whether the two paths name one file (existing or not).
bool sameFile(const std::string& a, const std::string& b);

// Throws CliError: exit 2 when an output would replace an input or another output, exit 1 when
// it cannot be written (a folder on its path is a file or cannot be written in, or the output is
// itself a folder, a device, a pipe or a socket).
void checkOutputFiles(const std::vector<OutputFile>& outputs, const std::vector<InputFile>& inputs);

// Why no file could be written at `path` (or `path` made as a folder, for `folder`), or "".
std::string unwritableReason(const std::string& path, bool folder);

}  // namespace candela::cli
