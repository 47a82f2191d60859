// What both fuzz targets do with a scene once its text is in place: what `candela info` does
// (load, validate, flatten, build the BVH), then a few camera paths, so that every value the
// loader lets through also reaches the kernel. Any exception other than SceneError, any
// sanitizer report, timeout or memory blow-up is a finding.
#pragma once

#include <string>

namespace candela::fuzz {

// Calls once per process: one worker thread, so that a run stays on the one core it was given.
void limitToOneThread();

// parseSceneText(text, label, baseDir) (what loadSceneFile does once it has read the file), then
// the rest as above. SceneError is the expected outcome of a bad input and is swallowed.
void loadAndTrace(const std::string& text, const std::string& baseDir);

}  // namespace candela::fuzz
