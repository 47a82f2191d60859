// Reading a whole file into memory, with the operating system's reason when that fails.
#pragma once

#include <string>

namespace candela {

// Reads the file at `path` byte for byte. On failure returns false and sets `reason` to the
// system's description, e.g. "No such file or directory", or to why it is no input file (a
// directory, a pipe or device, larger than core/input_file.h allows).
bool readTextFile(const std::string& path, std::string* contents, std::string* reason);

}  // namespace candela
