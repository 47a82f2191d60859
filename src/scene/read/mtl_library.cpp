// Reading MTL files; see mtl_library.h.
#include "scene/read/mtl_library.h"

#include <filesystem>
#include <sstream>

#include "scene/read/text_file.h"

namespace candela {

// Material names as tinyobjloader reads them: everything after "newmtl" and one blank.
static void collectStatements(const std::string& text, const std::string& label,
                              const std::string& folder, MtlLibrary& library) {
  std::istringstream lines(text);
  std::string line, current;
  size_t number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos) continue;
    const std::string statement = line.substr(start);
    const auto isKeyword = [&](const char* keyword, size_t length) {
      return statement.compare(0, length, keyword) == 0 && statement.size() > length &&
             (statement[length] == ' ' || statement[length] == '\t');
    };
    const auto keep = [&](size_t length) {
      std::string arguments = statement.substr(length);
      const size_t first = arguments.find_first_not_of(" \t");
      const size_t last = arguments.find_last_not_of(" \t");
      arguments = first == std::string::npos ? "" : arguments.substr(first, last - first + 1);
      return MtlStatement{label, folder, number, arguments};
    };
    MtlTextures& own = library.statements[current];
    if (isKeyword("newmtl", 6))
      current = statement.substr(7);
    else if (isKeyword("Kd", 2))
      library.kdNames.insert(current);
    else if (isKeyword("map_Kd", 6))
      own.mapKd = keep(6);
    else if (isKeyword("map_Ke", 6))
      own.mapKe = keep(6);
    else if (isKeyword("map_d", 5))
      own.mapD = keep(5);
    else if (isKeyword("norm", 4))
      own.norm = keep(4);
    else if (isKeyword("map_Pr", 6))
      own.mapPr = keep(6);
    else if (isKeyword("Pr", 2))
      own.pr = keep(2);
    else if (isKeyword("map_Pm", 6))
      own.mapPm = keep(6);
    else if (isKeyword("Pm", 2))
      own.pm = keep(2);
    else if (isKeyword("Pcr", 3))
      own.pcr = keep(3);
    else if (isKeyword("Pc", 2))
      own.pc = keep(2);
    else if (isKeyword("Ps", 2))
      own.ps = keep(2);
    else if (isKeyword("anisor", 6))
      own.anisor = keep(6);
    else if (isKeyword("aniso", 5))
      own.aniso = keep(5);
    else if (isKeyword("map_Bump", 8) || isKeyword("map_bump", 8) || isKeyword("bump", 4)) {
      own.bumpKeyword = statement.substr(0, statement.find_first_of(" \t"));
      own.bump = keep(own.bumpKeyword.size());
    } else if (isKeyword("d", 1))
      own.d = keep(1);
    else if (isKeyword("Tr", 2))
      own.tr = keep(2);
  }
}

MtlLibrary readMtlLibrary(const std::string& objPath, const std::string& objLabel,
                          const std::vector<NamedAtLine>& names) {
  const std::filesystem::path folder = std::filesystem::path(objPath).parent_path();
  const std::filesystem::path labelFolder = std::filesystem::path(objLabel).parent_path();
  MtlLibrary library;
  for (const NamedAtLine& named : names) {
    const std::string& name = named.name;
    std::string contents, reason;
    const std::string path = (folder / name).string();
    if (!readTextFile(path, &contents, &reason)) {
      library.unread.push_back(MtlLibrary::Unread{named, reason});
      continue;
    }
    library.files.push_back(path);
    collectStatements(contents, (labelFolder / name).string(),
                      std::filesystem::path(path).parent_path().string(), library);
    library.text += contents + "\n";
  }
  return library;
}

}  // namespace candela
