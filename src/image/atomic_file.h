// Whole-file I/O for image files: atomic replacement on write, whole reads.
//
// writeFileAtomically writes to a temporary file beside the target (".<name>.tmp-<pid>-<n>",
// the same directory so that the rename cannot cross file systems) and renames it into place:
// readers see either the old file or the complete new one, and an interrupted or failed write
// leaves no partial file behind.
#pragma once

#include <cstddef>
#include <string>

namespace candela {

// Throws ImageWriteError with the path and the reason (e.g. a missing directory, permission).
void writeFileAtomically(const std::string& path, const std::string& bytes);

// writeFileAtomically in two steps, for files that must appear together or not at all: construct
// one StagedFile per file (each writes and syncs its temporary file), then commit() each (a
// rename). One that is destroyed uncommitted removes its temporary file. A path that is a symbolic
// link replaces the file it points to, not the link.
class StagedFile {
 public:
  // Throws ImageWriteError as writeFileAtomically does.
  StagedFile(const std::string& path, const std::string& bytes);
  ~StagedFile();
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  // Renames the temporary file into place; throws ImageWriteError.
  void commit();

 private:
  std::string path_;    // as given, for messages
  std::string target_;  // the file the rename replaces: path_ with a link followed
  std::string temp_;    // empty once committed
};

// Throws ImageWriteError with the path and the reason.
std::string readFileBytes(const std::string& path);

// Removes the temporary files writeFileAtomically left in `dir` when its process died (killed
// mid-write): those whose process no longer runs. Returns how many it removed.
size_t removeStaleTemporaryFiles(const std::string& dir);

}  // namespace candela
