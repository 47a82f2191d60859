// What the fuzz targets share: what `candela info` does with a scene once its text is in place
// (load, validate, flatten, build the BVH), then a few camera paths, so that every value the
// loader lets through also reaches the kernel. Any exception other than SceneError, any
// sanitizer report, timeout or memory blow-up is a finding.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace candela::fuzz {

// Calls once per process: one worker thread, so that a run stays on the one core it was given.
void limitToOneThread();

// parseSceneText(text, label, baseDir) (what loadSceneFile does once it has read the file), then
// the rest as above. SceneError is the expected outcome of a bad input and is swallowed.
void loadAndTrace(const std::string& text, const std::string& baseDir);

// Makes this process's own folder under /tmp for the files its inputs become (`names`), so that
// parallel jobs never share files; the folder and those files go when the process exits.
// Returns the folder's path; aborts where it cannot be made.
std::string makeInputFolder(const std::string& target, const std::vector<std::string>& names);

// Writes `size` bytes from `data` to the file at `path`; aborts where it cannot.
void writeInput(const std::string& path, const void* data, size_t size);

}  // namespace candela::fuzz
