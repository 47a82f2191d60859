#include "scene/read/ply_header.h"

#include <charconv>
#include <string_view>

#include "scene/read/shown_text.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

struct TypeName {
  const char* name;
  PlyType type;
};

// Both spellings of the specification (and of every writer since).
constexpr TypeName kTypeNames[] = {
    {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::Uint8},
    {"uint8", PlyType::Uint8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::Uint16},  {"uint16", PlyType::Uint16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},    {"uint", PlyType::Uint32},     {"uint32", PlyType::Uint32},
    {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64}};

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

class HeaderReader {
 public:
  HeaderReader(const std::string& bytes, const std::string& label) : bytes_(bytes), label_(label) {}

  PlyHeader read() {
    if (nextLine() != "ply")
      fail("expected \"ply\" on the first line (a Stanford PLY file), got " + shownText(line_));
    bool formatSeen = false;
    for (;;) {
      if (offset_ >= bytes_.size()) fail("the header ends without \"end_header\"");
      const std::vector<std::string_view> w = words(nextLine());
      if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
      if (w[0] == "end_header") break;
      if (w[0] == "format") {
        format(w);
        formatSeen = true;
      } else if (w[0] == "element") {
        element(w);
      } else if (w[0] == "property") {
        property(w);
      } else {
        fail("unknown header statement " + shownText(w[0]) +
             " (expected format, element, property, comment or end_header)");
      }
    }
    if (!formatSeen) fail("the header has no \"format\" line");
    header_.bodyOffset = offset_;
    header_.lines = number_;
    return header_;
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const {
    throw SceneError(label_ + ":" + std::to_string(number_) + ": " + reason);
  }

  // The next line, without its \n or \r\n.
  std::string_view nextLine() {
    const std::string_view rest = std::string_view(bytes_).substr(offset_);
    size_t end = rest.find('\n');
    if (end == std::string_view::npos) end = rest.size();
    offset_ += end + (end < rest.size() ? 1 : 0);
    ++number_;
    line_ = rest.substr(0, end > 0 && rest[end - 1] == '\r' ? end - 1 : end);
    return line_;
  }

  void format(const std::vector<std::string_view>& w) {
    if (w.size() != 3 || w[2] != "1.0")
      fail(
          "expected \"format ascii 1.0\", \"format binary_little_endian 1.0\" or "
          "\"format binary_big_endian 1.0\", got " +
          shownText(line_));
    if (w[1] == "ascii") {
      header_.format = PlyFormat::Ascii;
    } else if (w[1] == "binary_little_endian") {
      header_.format = PlyFormat::BinaryLittleEndian;
    } else if (w[1] == "binary_big_endian") {
      header_.format = PlyFormat::BinaryBigEndian;
    } else {
      fail("unknown format " + shownText(w[1]) +
           " (expected ascii, binary_little_endian or binary_big_endian)");
    }
  }

  void element(const std::vector<std::string_view>& w) {
    uint64_t count = 0;
    const std::string_view n = w.size() == 3 ? w[2] : std::string_view();
    const auto parsed = std::from_chars(n.data(), n.data() + n.size(), count);
    if (w.size() != 3 || parsed.ec != std::errc() || parsed.ptr != n.data() + n.size())
      fail("expected \"element NAME COUNT\" with a whole COUNT, got " + shownText(line_));
    for (const PlyElement& e : header_.elements)
      if (e.name == w[1]) fail("a second element " + shownText(w[1]));
    header_.elements.push_back(PlyElement{std::string(w[1]), count, {}, number_});
  }

  PlyType type(std::string_view name) const {
    for (const TypeName& t : kTypeNames)
      if (name == t.name) return t.type;
    fail("unknown property type " + shownText(name) +
         " (expected char, uchar, short, ushort, int, uint, float or double)");
  }

  void property(const std::vector<std::string_view>& w) {
    if (header_.elements.empty()) fail("a property before any element");
    PlyProperty p;
    if (w.size() == 5 && w[1] == "list") {
      p.isList = true;
      p.countType = type(w[2]);
      if (p.countType == PlyType::Float32 || p.countType == PlyType::Float64)
        fail("a list's count must be of an integer type, got " + shownText(w[2]));
      p.type = type(w[3]);
      p.name = std::string(w[4]);
    } else if (w.size() == 3 && w[1] != "list") {
      p.type = type(w[1]);
      p.name = std::string(w[2]);
    } else {
      fail("expected \"property TYPE NAME\" or \"property list COUNT_TYPE TYPE NAME\", got " +
           shownText(line_));
    }
    std::vector<PlyProperty>& properties = header_.elements.back().properties;
    for (const PlyProperty& q : properties)
      if (q.name == p.name) fail("a second property " + shownText(p.name));
    properties.push_back(p);
  }

  const std::string& bytes_;
  const std::string& label_;
  PlyHeader header_;
  size_t offset_ = 0, number_ = 0;
  std::string_view line_;
};

}  // namespace

size_t plySize(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::Uint8:
      return 1;
    case PlyType::Int16:
    case PlyType::Uint16:
      return 2;
    case PlyType::Int32:
    case PlyType::Uint32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

const char* plyTypeName(PlyType type) {
  for (const TypeName& t : kTypeNames)  // each type's first name is the specification's
    if (t.type == type) return t.name;
  return "?";
}

PlyHeader readPlyHeader(const std::string& bytes, const std::string& label) {
  return HeaderReader(bytes, label).read();
}

}  // namespace candela
