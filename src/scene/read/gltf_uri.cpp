// glTF URIs as files; see gltf_uri.h.
#include "scene/read/gltf_uri.h"

#include <cctype>
#include <cstdlib>

#include "scene/read/resolve_path.h"

namespace candela {

std::string gltfUriPath(const std::string& uri, const std::string& folder) {
  std::string decoded;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(uint8_t(uri[i + 1])) &&
        std::isxdigit(uint8_t(uri[i + 2]))) {
      decoded += char(std::strtol(uri.substr(i + 1, 2).c_str(), nullptr, 16));
      i += 2;
    } else {
      decoded += uri[i];
    }
  }
  return resolvePath(decoded, folder);
}

}  // namespace candela
