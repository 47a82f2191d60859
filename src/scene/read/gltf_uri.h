// The file a glTF URI names: its percent-escapes decoded (RFC 3986: "my%20texture.png"), relative
// to the folder of the glTF file unless absolute.
#pragma once

#include <string>

namespace candela {

std::string gltfUriPath(const std::string& uri, const std::string& folder);

// Whether a URI holds its data itself ("data:...;base64,...").
inline bool isDataUri(const std::string& uri) { return uri.compare(0, 5, "data:") == 0; }

}  // namespace candela
