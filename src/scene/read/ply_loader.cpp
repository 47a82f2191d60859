#include "scene/read/ply_loader.h"

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "core/texture.h"
#include "scene/read/ply_header.h"
#include "scene/read/polygon_triangulation.h"
#include "scene/read/shown_text.h"
#include "scene/read/text_file.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

bool hostIsLittleEndian() {
  const uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

bool isInteger(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64; }

// The body's values one after another, each as a double (which holds every PLY type exactly),
// with the element and number being read for messages.
class Body {
 public:
  Body(const std::string& bytes, const PlyHeader& header, const std::string& label)
      : bytes_(bytes),
        label_(label),
        ascii_(header.format == PlyFormat::Ascii),
        swap_((header.format == PlyFormat::BinaryBigEndian) == hostIsLittleEndian()),
        offset_(header.bodyOffset),
        line_(header.lines + 1) {}

  void at(const std::string& element, uint64_t index) {
    element_ = &element;
    index_ = index;
  }

  [[noreturn]] void fail(const std::string& reason) const {
    const std::string where = ascii_ ? label_ + ":" + std::to_string(line_) : label_;
    throw SceneError(where + ": " + *element_ + " " + std::to_string(index_) + ": " + reason);
  }

  double value(PlyType type) { return ascii_ ? asciiValue(type) : binaryValue(type); }

  // A list's count: a whole number, which the bytes left must be able to hold.
  uint64_t count(PlyType type, PlyType itemType) {
    const double n = value(type);
    if (n < 0) fail("a list of " + std::to_string(int64_t(n)) + " items");
    const size_t itemBytes = ascii_ ? 2 : plySize(itemType);
    if (n * double(itemBytes) > double(bytes_.size() - offset_) + 1)
      fail("a list of " + std::to_string(uint64_t(n)) + " items, more than the file holds");
    return uint64_t(n);
  }

  void skip(const PlyProperty& p) {
    const uint64_t n = p.isList ? count(p.countType, p.type) : 1;
    for (uint64_t i = 0; i < n; ++i) value(p.type);
  }

  // The fewest bytes an element of these properties can take, to bound what a count reserves.
  size_t minimumBytes(const std::vector<PlyProperty>& properties) const {
    size_t bytes = 0;
    for (const PlyProperty& p : properties)
      bytes += ascii_ ? 2 : plySize(p.isList ? p.countType : p.type);
    return std::max<size_t>(bytes, 1);
  }
  size_t bytesLeft() const { return bytes_.size() - offset_; }

 private:
  double asciiValue(PlyType type) {
    while (offset_ < bytes_.size() && isBlank(bytes_[offset_])) {
      if (bytes_[offset_] == '\n') ++line_;
      ++offset_;
    }
    if (offset_ >= bytes_.size()) fail("the file ends here");
    size_t end = offset_;
    while (end < bytes_.size() && !isBlank(bytes_[end])) ++end;
    const char* first = bytes_.data() + offset_;
    const char* last = bytes_.data() + end;
    double v = 0;
    const auto parsed = std::from_chars(first, last, v);
    const std::string_view token(first, size_t(last - first));
    if (parsed.ptr != last ||
        (parsed.ec != std::errc() && parsed.ec != std::errc::result_out_of_range))
      fail("expected a number, got " + shownText(token));
    if (parsed.ec == std::errc::result_out_of_range) {
      // As the OBJ reader: below the smallest double reads as 0, beyond the largest is refused.
      v = std::strtod(std::string(token).c_str(), nullptr);
      if (!std::isfinite(v)) fail("the number " + shownText(token) + " is out of range");
    }
    if (isInteger(type) && !(v == std::floor(v) && inRange(v, type)))
      fail(std::string("expected an integer of type ") + plyTypeName(type) + ", got " +
           shownText(token));
    offset_ = end;
    return v;
  }

  static bool inRange(double v, PlyType type) {
    switch (type) {
      case PlyType::Int8:
        return v >= -128 && v <= 127;
      case PlyType::Uint8:
        return v >= 0 && v <= 255;
      case PlyType::Int16:
        return v >= -32768 && v <= 32767;
      case PlyType::Uint16:
        return v >= 0 && v <= 65535;
      case PlyType::Int32:
        return v >= -2147483648.0 && v <= 2147483647.0;
      case PlyType::Uint32:
        return v >= 0 && v <= 4294967295.0;
      default:
        return true;
    }
  }

  double binaryValue(PlyType type) {
    const size_t n = plySize(type);
    if (n > bytes_.size() - offset_) fail("the file ends here");
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + offset_, n);
    offset_ += n;
    if (swap_) std::reverse(b, b + n);
    switch (type) {
      case PlyType::Int8:
        return double(int8_t(b[0]));
      case PlyType::Uint8:
        return double(b[0]);
      case PlyType::Int16:
        return load<int16_t>(b);
      case PlyType::Uint16:
        return load<uint16_t>(b);
      case PlyType::Int32:
        return load<int32_t>(b);
      case PlyType::Uint32:
        return load<uint32_t>(b);
      case PlyType::Float32:
        return load<float>(b);
      case PlyType::Float64:
        return load<double>(b);
    }
    return 0;
  }

  template <typename T>
  static double load(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof v);
    return double(v);
  }

  const std::string& bytes_;
  const std::string& label_;
  const bool ascii_, swap_;
  size_t offset_, line_;
  const std::string* element_ = nullptr;
  uint64_t index_ = 0;
};

// Where a property of the vertex element goes: its index in the element, or -1.
struct VertexLayout {
  int position[3] = {-1, -1, -1}, normal[3] = {-1, -1, -1}, uv[2] = {-1, -1};
  int colour[3] = {-1, -1, -1};
};

// What a colour property's largest value is: an integer type's largest (uchar 255), 1 for floats.
double colourScale(PlyType type) {
  switch (type) {
    case PlyType::Int8:
      return 127.0;
    case PlyType::Uint8:
      return 255.0;
    case PlyType::Int16:
      return 32767.0;
    case PlyType::Uint16:
      return 65535.0;
    case PlyType::Int32:
      return 2147483647.0;
    case PlyType::Uint32:
      return 4294967295.0;
    default:
      return 1.0;
  }
}

[[noreturn]] void failAtLine(const std::string& label, size_t line, const std::string& reason) {
  throw SceneError(label + ":" + std::to_string(line) + ": " + reason);
}

VertexLayout vertexLayout(const PlyElement& vertex, const std::string& label) {
  VertexLayout layout;
  const auto find = [&](const char* name) {
    for (size_t i = 0; i < vertex.properties.size(); ++i)
      if (vertex.properties[i].name == name && !vertex.properties[i].isList) return int(i);
    return -1;
  };
  const char* const axes[3][2] = {{"x", "nx"}, {"y", "ny"}, {"z", "nz"}};
  for (int a = 0; a < 3; ++a) {
    layout.position[a] = find(axes[a][0]);
    layout.normal[a] = find(axes[a][1]);
    if (layout.position[a] < 0)
      failAtLine(label, vertex.line,
                 std::string("the vertex element has no property ") + axes[a][0]);
  }
  if (std::min({layout.normal[0], layout.normal[1], layout.normal[2]}) < 0)
    layout.normal[0] = layout.normal[1] = layout.normal[2] = -1;
  const char* const uvNames[4][2] = {
      {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
  for (const auto& pair : uvNames)
    if (layout.uv[0] < 0 && find(pair[0]) >= 0 && find(pair[1]) >= 0) {
      layout.uv[0] = find(pair[0]);
      layout.uv[1] = find(pair[1]);
    }
  const char* const colourNames[3][3] = {
      {"red", "green", "blue"}, {"diffuse_red", "diffuse_green", "diffuse_blue"}, {"r", "g", "b"}};
  for (const auto& names : colourNames)
    if (layout.colour[0] < 0 && find(names[0]) >= 0 && find(names[1]) >= 0 && find(names[2]) >= 0)
      for (int c = 0; c < 3; ++c) layout.colour[c] = find(names[c]);
  return layout;
}

size_t reservation(const Body& body, const PlyElement& element) {
  return size_t(
      std::min<uint64_t>(element.count, body.bytesLeft() / body.minimumBytes(element.properties)));
}

void readVertices(Body& body, const PlyElement& element, const VertexLayout& layout,
                  MeshDesc& mesh) {
  const size_t reserve = reservation(body, element);
  mesh.positions.reserve(reserve);
  if (layout.normal[0] >= 0) mesh.normals.reserve(reserve);
  if (layout.uv[0] >= 0) mesh.uvs.reserve(reserve);
  if (layout.colour[0] >= 0) mesh.colors.reserve(reserve);
  std::vector<double> values(element.properties.size());
  for (uint64_t i = 0; i < element.count; ++i) {
    body.at(element.name, i);
    for (size_t k = 0; k < element.properties.size(); ++k) {
      const PlyProperty& p = element.properties[k];
      if (p.isList) {
        body.skip(p);
        continue;
      }
      values[k] = body.value(p.type);
      if (!std::isfinite(values[k]))
        body.fail(p.name + " is " + formatNumber(values[k]) + "; expected a finite number");
      if (std::fabs(values[k]) > FLT_MAX)
        body.fail(p.name + " is " + formatNumber(values[k]) + ", beyond single precision");
    }
    const auto at = [&](int k) { return float(values[size_t(k)]); };
    mesh.positions.push_back(
        Vec3(at(layout.position[0]), at(layout.position[1]), at(layout.position[2])));
    if (layout.normal[0] >= 0)
      mesh.normals.push_back(
          Vec3(at(layout.normal[0]), at(layout.normal[1]), at(layout.normal[2])));
    if (layout.uv[0] >= 0) mesh.uvs.push_back(Vec2(at(layout.uv[0]), at(layout.uv[1])));
    if (layout.colour[0] >= 0) {
      // Display colours, as scanners and MeshLab write them: sRGB-encoded, linear here.
      Vec3 linear;
      for (int c = 0; c < 3; ++c) {
        const PlyProperty& p = element.properties[size_t(layout.colour[c])];
        const double v = values[size_t(layout.colour[c])] / colourScale(p.type);
        if (!(v >= 0.0 && v <= 1.0))
          body.fail(p.name + " is " + formatNumber(values[size_t(layout.colour[c])]) +
                    "; expected a colour from 0 to " + formatNumber(colourScale(p.type)));
        linear[c] = srgbToLinearValue(float(v));
      }
      mesh.colors.push_back(linear);
    }
  }
}

// The faces' corners as the file lists them, each face's from starts[i] to starts[i + 1].
struct Polygons {
  std::vector<uint32_t> corners;
  std::vector<size_t> starts{0};
};

void readFaces(Body& body, const PlyElement& element, size_t list, uint64_t vertexCount,
               Polygons& polygons) {
  polygons.starts.reserve(reservation(body, element) + 1);
  for (uint64_t i = 0; i < element.count; ++i) {
    body.at(element.name, i);
    for (size_t k = 0; k < element.properties.size(); ++k) {
      const PlyProperty& p = element.properties[k];
      if (k != list) {
        body.skip(p);
        continue;
      }
      const uint64_t n = body.count(p.countType, p.type);
      if (n < 3) body.fail("a face of " + std::to_string(n) + " corners; expected at least 3");
      for (uint64_t c = 0; c < n; ++c) {
        const double index = body.value(p.type);
        if (!(index >= 0 && index < double(vertexCount) && index == std::floor(index)))
          body.fail("vertex index " + formatNumber(index) + " out of range (" +
                    std::to_string(vertexCount) + " vertices)");
        polygons.corners.push_back(uint32_t(index));
      }
      polygons.starts.push_back(polygons.corners.size());
    }
  }
}

// Triangles as an OBJ face's: a quad split along its shorter diagonal, measured in float as
// tinyobjloader does (so that a quad mesh reads alike from either format), a larger polygon by
// triangulatePolygon.
void triangulate(const Polygons& polygons, const std::string& label, MeshDesc& mesh) {
  const auto corner = [&](size_t i) { return mesh.positions[polygons.corners[i]]; };
  std::vector<Vec3> positions;
  std::vector<CornerTriangle> triangles;
  for (size_t face = 0; face + 1 < polygons.starts.size(); ++face) {
    const size_t first = polygons.starts[face], n = polygons.starts[face + 1] - first;
    triangles.clear();
    if (n == 3) {
      triangles.push_back({0, 1, 2});
    } else if (n == 4) {
      const Vec3 e02 = corner(first + 2) - corner(first),
                 e13 = corner(first + 3) - corner(first + 1);
      if (dot(e02, e02) < dot(e13, e13)) {
        triangles.push_back({0, 1, 2});
        triangles.push_back({0, 2, 3});
      } else {
        triangles.push_back({0, 1, 3});
        triangles.push_back({1, 2, 3});
      }
    } else {
      positions.clear();
      for (size_t c = 0; c < n; ++c) positions.push_back(corner(first + c));
      if (!triangulatePolygon(positions, &triangles))
        throw SceneError(label + ": face " + std::to_string(face) + ": a concave face of " +
                         std::to_string(n) +
                         " corners; a face that is not convex may have at most " +
                         std::to_string(kMaxConcaveFaceCorners) + " (split it into smaller faces)");
    }
    for (const CornerTriangle& t : triangles) {
      MeshTriangle triangle{};
      for (int k = 0; k < 3; ++k) {
        triangle.v[k] = polygons.corners[first + t[size_t(k)]];
        triangle.n[k] = mesh.normals.empty() ? -1 : int32_t(triangle.v[k]);
        triangle.t[k] = mesh.uvs.empty() ? -1 : int32_t(triangle.v[k]);
      }
      triangle.material = 0;
      mesh.triangles.push_back(triangle);
    }
  }
}

const PlyElement* findElement(const PlyHeader& header, const char* name) {
  for (const PlyElement& e : header.elements)
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace

bool isPlyPath(const std::string& path) {
  if (path.size() < 4) return false;
  std::string extension = path.substr(path.size() - 4);
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".ply";
}

MeshDesc loadPlyFile(const std::string& path, const std::string& label) {
  std::string bytes, reason;
  if (!readTextFile(path, &bytes, &reason))
    throw SceneError("cannot open \"" + label + "\" (" + reason + ")");
  const PlyHeader header = readPlyHeader(bytes, label);
  const PlyElement* vertex = findElement(header, "vertex");
  const PlyElement* face = findElement(header, "face");
  if (!vertex) throw SceneError(label + ": the header has no vertex element");
  if (!face || face->count == 0)
    throw SceneError(label + ": expected a mesh, got no faces (a point cloud?)");
  if (vertex->count >= std::numeric_limits<uint32_t>::max())
    failAtLine(label, vertex->line,
               std::to_string(vertex->count) + " vertices, more than a mesh may have (4294967294)");
  const VertexLayout layout = vertexLayout(*vertex, label);
  size_t list = face->properties.size();
  for (size_t k = 0; k < face->properties.size(); ++k)
    if (face->properties[k].isList && (face->properties[k].name == "vertex_indices" ||
                                       face->properties[k].name == "vertex_index"))
      list = k;
  if (list == face->properties.size())
    failAtLine(label, face->line, "the face element has no list property vertex_indices");

  MeshDesc mesh;
  Polygons polygons;
  Body body(bytes, header, label);
  for (const PlyElement& element : header.elements) {
    if (&element == vertex) {
      readVertices(body, element, layout, mesh);
    } else if (&element == face) {
      readFaces(body, element, list, vertex->count, polygons);
    } else if (!element.properties.empty()) {  // an element of none takes no bytes, however many
      for (uint64_t i = 0; i < element.count; ++i) {
        body.at(element.name, i);
        for (const PlyProperty& p : element.properties) body.skip(p);
      }
    }
  }
  triangulate(polygons, label, mesh);
  // Diffuse 0.8, as an OBJ face without a material; diffuse 1 under vertex colours, which then
  // are its colour.
  mesh.materials.push_back(Material{});
  if (!mesh.colors.empty()) mesh.materials.back().color = Vec3(1.0f);
  return mesh;
}

}  // namespace candela
