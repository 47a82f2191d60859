// Reading MTL files; see mtl_library.h.
#include "scene/read/mtl_library.h"

#include <filesystem>
#include <sstream>

#include "scene/read/text_file.h"

namespace candela {

// Material names as tinyobjloader reads them: everything after "newmtl" and one blank.
static void collectKdNames(const std::string& text, std::set<std::string>& kdNames) {
  std::istringstream lines(text);
  std::string line, current;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos) continue;
    const std::string statement = line.substr(start);
    const auto isKeyword = [&](const char* keyword, size_t length) {
      return statement.compare(0, length, keyword) == 0 && statement.size() > length &&
             (statement[length] == ' ' || statement[length] == '\t');
    };
    if (isKeyword("newmtl", 6))
      current = statement.substr(7);
    else if (isKeyword("Kd", 2))
      kdNames.insert(current);
  }
}

MtlLibrary readMtlLibrary(const std::string& objPath, const std::vector<std::string>& names) {
  const std::filesystem::path folder = std::filesystem::path(objPath).parent_path();
  MtlLibrary library;
  for (const std::string& name : names) {
    std::string contents, reason;
    const std::string path = (folder / name).string();
    if (!readTextFile(path, &contents, &reason)) continue;
    library.files.push_back(path);
    collectKdNames(contents, library.kdNames);
    library.text += contents + "\n";
  }
  return library;
}

}  // namespace candela
