// Checking outputs against inputs and each other; see output_check.h.
#include "apps/cli/output_check.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "apps/cli/cli_error.h"

namespace fs = std::filesystem;

namespace candela::cli {

std::vector<InputFile> inputFiles(const std::vector<SceneDesc>& scenes) {
  std::vector<InputFile> files;
  for (const SceneDesc& scene : scenes) {
    files.push_back({scene.file, "the scene file"});
    if (!scene.camera.gltfFile.empty())
      files.push_back({scene.camera.gltfFile, "the camera's glTF file"});
    std::string lightFile;  // a glTF file's lights are consecutive
    for (const LightDesc& light : scene.lights)
      if (!light.gltfFile.empty() && light.gltfFile != lightFile)
        files.push_back({lightFile = light.gltfFile, "the lights' glTF file"});
    for (const ObjectDesc& object : scene.objects) {
      if (!object.file.empty()) files.push_back({object.file, "the mesh"});
      for (const std::string& mtl : object.mesh->materialFiles)
        files.push_back({mtl, "the material library"});
      for (const std::string& buffer : object.mesh->bufferFiles)
        files.push_back({buffer, "the mesh's buffer"});
    }
    if (!scene.environment.map.empty())
      files.push_back({scene.environment.map, "the environment map"});
    for (const auto& texture : scene.textures) files.push_back({texture->file, "a texture"});
  }
  return files;
}

namespace {

// The absolute path with links and "." and ".." resolved as far as it exists, and no trailing
// separator ("out/" and "out" are one folder); empty when that fails.
fs::path resolved(const std::string& path) {
  std::error_code error;
  // Absolute first: of a path none of whose start exists, weakly_canonical keeps it relative.
  const fs::path absolute = fs::absolute(path, error);
  if (error) return {};
  fs::path p = fs::weakly_canonical(absolute, error);
  if (error) return {};
  if (!p.has_filename() && p.has_relative_path()) p = p.parent_path();
  return p;
}

}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::equivalent(a, b, error)) return true;  // both exist: one file, hard links included
  const fs::path ra = resolved(a);
  return !ra.empty() && ra == resolved(b);
}

std::string unwritableReason(const std::string& path, bool folder) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::is_directory(status)) {
    if (!folder) return "is a folder, not a file";
  } else if (fs::exists(status)) {
    if (folder) return "is a file, not a folder";
    // Renaming a file into place would replace the device or pipe itself (/dev/null, say).
    if (!fs::is_regular_file(status)) return "is a device, pipe or socket, not a regular file";
  }
  // The nearest folder that exists must be one and must let us create entries in it (for a link,
  // the folder of the file it points to, which is the one replaced).
  const fs::path file =
      fs::is_symlink(path, error) ? fs::weakly_canonical(path, error) : fs::path(path);
  fs::path existing = fs::is_directory(status) ? file : file.parent_path();
  while (!existing.empty() && !fs::exists(existing, error)) existing = existing.parent_path();
  if (existing.empty()) existing = ".";
  if (!fs::is_directory(existing, error)) return "'" + existing.string() + "' is not a folder";
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    return "cannot write in '" + existing.string() + "': " + std::strerror(errno);
  return "";
}

void checkOutputFiles(const std::vector<OutputFile>& outputs,
                      const std::vector<InputFile>& inputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const OutputFile& out = outputs[i];
    for (const InputFile& in : inputs)
      if (sameFile(out.path, in.path))
        throw CliError(kExitUsage, out.path + ": " + out.option + " would overwrite " + in.kind +
                                       " " + in.path + ", which the render reads");
    for (size_t j = 0; j < i; ++j)
      if (sameFile(out.path, outputs[j].path))
        throw CliError(kExitUsage, out.path + ": " + outputs[j].option + " and " + out.option +
                                       " name the same file; give each its own");
    const std::string reason = unwritableReason(out.path, false);
    if (!reason.empty()) throw CliError(kExitFailure, out.path + ": cannot write there: " + reason);
  }
}

}  // namespace candela::cli
