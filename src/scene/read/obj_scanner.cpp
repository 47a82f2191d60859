// OBJ validation pass; see obj_scanner.h.
#include "scene/read/obj_scanner.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <unordered_set>

#include "scene/read/polygon_triangulation.h"
#include "scene/read/shown_text.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// Statements of the OBJ specification (and tinyobjloader's extensions "vw" and "t") that carry
// nothing a path tracer draws: free-form geometry, display and grouping attributes (of which "g"
// and "o" pass on to tinyobjloader, whose shapes they name: an object's "obj_group").
constexpr std::string_view kIgnoredStatements[] = {
    "vp",         "cstype",    "deg",   "bmat",  "step",     "curv",     "curv2", "surf",
    "parm",       "trim",      "hole",  "scrv",  "sp",       "end",      "con",   "g",
    "s",          "mg",        "o",     "bevel", "c_interp", "d_interp", "lod",   "usemtl",
    "shadow_obj", "trace_obj", "ctech", "stech", "maplib",   "usemap",   "vw",    "t"};

bool isBlank(char c) { return c == ' ' || c == '\t'; }

// The blank-separated tokens of `line` into *tokens (cleared first).
void tokenize(std::string_view line, std::vector<std::string_view>* tokens) {
  tokens->clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    if (i > start) tokens->push_back(line.substr(start, i - start));
  }
}

// The value of `token`, a number of isObjNumber's grammar, as strtod reads it (from_chars, which
// rounds alike, but takes no '+' and leaves values beyond double's range to strtod).
double parseNumber(std::string_view token) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  double value = 0.0;
  const std::from_chars_result parsed =
      std::from_chars(token.data(), token.data() + token.size(), value);
  if (parsed.ec == std::errc()) return value;
  return std::strtod(std::string(token).c_str(), nullptr);
}

// The value of `digits`, an optional sign and at most 18 decimal digits.
long long parseIndex(std::string_view digits) {
  if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
  long long value = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), value);
  return value;
}

// Where the first line of `text` ends: its first \n or \r, npos if neither. (string_view's
// find_first_of calls memchr on the set for every character.)
size_t lineEnd(std::string_view text) {
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n' || text[i] == '\r') return i;
  return std::string_view::npos;
}

// The number grammar tinyobjloader reads: [+-] digits [. digits] [e [+-] digits], where the
// mantissa may start or end with the dot but must hold a digit.
bool isObjNumber(std::string_view t) {
  size_t i = 0, digits = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  for (; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i) ++digits;
  if (i < t.size() && t[i] == '.')
    for (++i; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i) ++digits;
  if (digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    size_t exponentDigits = 0;
    for (; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i) ++exponentDigits;
    if (exponentDigits == 0) return false;
  }
  return i == t.size();
}

std::string counted(long long count, const char* singular, const char* plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

// Whether a statement goes on to the next line: its last character but blanks is a backslash
// (the OBJ specification's continuation). A comment never does: a Windows path at its end would
// swallow the data line after it.
bool continues(std::string_view line) {
  const size_t last = line.find_last_not_of(" \t");
  const size_t first = line.find_first_not_of(" \t");
  return last != std::string_view::npos && line[last] == '\\' && line[first] != '#';
}

class Scanner {
 public:
  explicit Scanner(const std::string& label) : label_(label) {}

  void scanLine(std::string_view line, size_t number, ObjScan& out);

 private:
  [[noreturn]] void fail(const std::string& reason) const {
    throw SceneError(label_ + ":" + std::to_string(line_) + ": " + reason);
  }
  void numbers(const std::vector<std::string_view>& tokens, size_t min, size_t max,
               const char* form, std::string_view line, double* values) const;
  void references(const std::vector<std::string_view>& tokens, size_t min, const char* form,
                  const char* indexName, std::string_view line) const;
  void reference(std::string_view token, const char* indexName) const;
  void index(std::string_view digits, std::string_view token, long long count,
             const std::string& name, const char* singular, const char* plural) const;
  void materialLibraries(std::string_view arguments, ObjScan& out);
  void materialUse(std::string_view arguments, ObjScan& out);
  void polygon(const std::vector<std::string_view>& tokens, ObjScan& out) const;

  const std::string& label_;
  size_t line_ = 0;
  long long vertices_ = 0, texcoords_ = 0, normals_ = 0;
  std::vector<Vec3> positions_;           // of the vertices so far, for triangulating polygons
  std::vector<std::string_view> tokens_;  // the current line's, reused from line to line
  // The names in ObjScan's materialLibraries and materialUses, so that a file of many is not
  // searched line by line.
  std::unordered_set<std::string> libraryNames_, useNames_;
};

void Scanner::scanLine(std::string_view line, size_t number, ObjScan& out) {
  line_ = number;
  const size_t first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos || line[first] == '#') {
    out.text += '\n';
    return;
  }
  const size_t keywordEnd = std::min(line.size(), line.find_first_of(" \t", first));
  const std::string_view keyword = line.substr(first, keywordEnd - first);
  const bool data = keyword == "v" || keyword == "vn" || keyword == "vt" || keyword == "f" ||
                    keyword == "l" || keyword == "p";
  if (!data) {
    if (keyword == "mtllib") {
      materialLibraries(line.substr(keywordEnd), out);
    } else if (keyword == "usemtl") {
      materialUse(line.substr(keywordEnd), out);
    } else if (std::find(std::begin(kIgnoredStatements), std::end(kIgnoredStatements), keyword) ==
               std::end(kIgnoredStatements)) {
      fail("unknown statement " + shownText(keyword));
    } else if (keyword != "g" && keyword != "o") {
      out.text += '\n';  // unused, and unchecked: tinyobjloader must not parse it either
      return;
    }
    // A group's or object's name passes, which names tinyobjloader's shapes (an "obj_group").
    out.text.append(line.data(), line.size());
    out.text += '\n';
    return;
  }
  // Data lines may end in a comment; tinyobjloader would read it as a face index.
  const std::string_view content = line.substr(0, line.find('#'));
  tokenize(content, &tokens_);
  tokens_.erase(tokens_.begin());
  const std::vector<std::string_view>& tokens = tokens_;
  std::string_view whole = content.substr(first);
  while (!whole.empty() && isBlank(whole.back())) whole.remove_suffix(1);
  if (keyword == "v") {
    double values[7];
    numbers(tokens, 3, 7, "a vertex \"v x y z\"", whole, values);
    // Six numbers or more: a colour after the position ("v x y z r g b", MeshLab's and ZBrush's
    // extension), as tinyobjloader reads it.
    if (tokens.size() >= 6)
      for (int c = 3; c < 6; ++c)
        if (!(values[c] >= 0.0 && values[c] <= 1.0))
          fail("expected a vertex colour \"v x y z r g b\" of numbers from 0 to 1, got " +
               shownText(tokens[size_t(c)]));
    positions_.push_back(Vec3(float(values[0]), float(values[1]), float(values[2])));
    ++vertices_;
    ++out.vertices;
    if (tokens.size() >= 6)
      ++out.colouredVertices;
    else if (out.firstUncolouredLine == 0)
      out.firstUncolouredLine = line_;
  } else if (keyword == "vn") {
    double values[3];
    numbers(tokens, 3, 3, "a normal \"vn x y z\"", whole, values);
    ++normals_;
  } else if (keyword == "vt") {
    double values[3];
    numbers(tokens, 1, 3, "a texture coordinate \"vt u [v [w]]\"", whole, values);
    ++texcoords_;
  } else if (keyword == "f") {
    references(tokens, 3, "a face with at least 3 vertices", "face index", whole);
    if (tokens.size() > 4) {
      polygon(tokens, out);
      return;
    }
  } else if (keyword == "l") {
    references(tokens, 2, "a line with at least 2 vertices", "vertex index", whole);
    out.text += '\n';  // checked, but not rendered
    return;
  } else {
    references(tokens, 1, "a point with at least 1 vertex", "vertex index", whole);
    out.text += '\n';
    return;
  }
  out.text.append(keyword.data(), keyword.size());
  for (std::string_view token : tokens) {
    out.text += ' ';
    out.text.append(token.data(), token.size());
  }
  out.text += '\n';
}

// Checks that `tokens` are min to max finite numbers and writes their values to values[].
void Scanner::numbers(const std::vector<std::string_view>& tokens, size_t min, size_t max,
                      const char* form, std::string_view line, double* values) const {
  if (tokens.size() < min || tokens.size() > max)
    fail(std::string("expected ") + form + ", got " + shownText(line));
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (!isObjNumber(tokens[i])) fail("expected a number, got " + shownText(tokens[i]));
    values[i] = parseNumber(tokens[i]);
    if (!(std::fabs(values[i]) <= FLT_MAX))
      fail("expected a finite number, got " + shownText(tokens[i]));
  }
}

void Scanner::references(const std::vector<std::string_view>& tokens, size_t min, const char* form,
                         const char* indexName, std::string_view line) const {
  if (tokens.size() < min) fail(std::string("expected ") + form + ", got " + shownText(line));
  for (std::string_view token : tokens) reference(token, indexName);
}

// One corner: v, v/vt, v//vn or v/vt/vn.
void Scanner::reference(std::string_view token, const char* indexName) const {
  const auto slashes = std::count(token.begin(), token.end(), '/');
  const size_t first = token.find('/');
  const size_t second = slashes == 2 ? token.find('/', first + 1) : std::string_view::npos;
  const std::string_view vertex = token.substr(0, first);
  const std::string_view texcoord =
      slashes >= 1
          ? token.substr(first + 1, second == std::string_view::npos ? std::string_view::npos
                                                                     : second - first - 1)
          : std::string_view();
  const std::string_view normal = slashes == 2 ? token.substr(second + 1) : std::string_view();
  const bool wellFormed = slashes <= 2 && !vertex.empty() && (slashes != 1 || !texcoord.empty()) &&
                          (slashes != 2 || !normal.empty());
  if (!wellFormed)
    fail("expected a vertex reference such as 1, 1/2, 1//3 or 1/2/3, got " + shownText(token));
  index(vertex, token, vertices_, indexName, "vertex", "vertices");
  if (!texcoord.empty())
    index(texcoord, token, texcoords_, "texture coordinate index", "texture coordinate",
          "texture coordinates");
  if (!normal.empty()) index(normal, token, normals_, "normal index", "normal", "normals");
}

// A 1-based index, or negative to count back from the latest element.
void Scanner::index(std::string_view digits, std::string_view token, long long count,
                    const std::string& name, const char* singular, const char* plural) const {
  size_t i = (digits[0] == '-' || digits[0] == '+') ? 1 : 0;
  const bool numeric = i < digits.size() && digits.size() - i <= 18 &&
                       std::all_of(digits.begin() + i, digits.end(), [](char c) {
                         return std::isdigit(static_cast<unsigned char>(c)) != 0;
                       });
  if (!numeric)
    fail("expected a vertex reference such as 1, 1/2, 1//3 or 1/2/3, got " + shownText(token));
  const long long value = parseIndex(digits);
  if (value == 0) fail(name + " 0 is invalid (OBJ indices start at 1)");
  if (value > count || value < -count)
    fail(name + " " + std::to_string(value) + " out of range (" + counted(count, singular, plural) +
         ")");
}

// File names after `mtllib`, separated by blanks; a backslash escapes the next character, as
// tinyobjloader reads them.
void Scanner::materialLibraries(std::string_view arguments, ObjScan& out) {
  std::string name;
  auto flush = [&] {
    if (!name.empty() && libraryNames_.insert(name).second)
      out.materialLibraries.push_back(NamedAtLine{name, line_});
    name.clear();
  };
  for (size_t i = 0; i < arguments.size(); ++i) {
    if (arguments[i] == '\\' && i + 1 < arguments.size()) {
      name += arguments[++i];
    } else if (isBlank(arguments[i])) {
      flush();
    } else {
      name += arguments[i];
    }
  }
  flush();
}

// The material name after `usemtl`: its first word, as tinyobjloader reads it.
void Scanner::materialUse(std::string_view arguments, ObjScan& out) {
  const size_t first = arguments.find_first_not_of(" \t");
  if (first == std::string_view::npos) return;
  std::string word(arguments.substr(first, arguments.find_first_of(" \t\r", first) - first));
  if (useNames_.insert(word).second) out.materialUses.push_back(NamedAtLine{word, line_});
}

// A face of more than four corners goes to tinyobjloader as triangles, which keep the corners'
// references as written (tinyobjloader's own ear clipping takes quadratic time and more, and may
// drop a face); quads it splits itself, along the shorter diagonal.
void Scanner::polygon(const std::vector<std::string_view>& tokens, ObjScan& out) const {
  std::vector<Vec3> corners;
  corners.reserve(tokens.size());
  for (std::string_view token : tokens) {
    const long long index = parseIndex(token.substr(0, token.find('/')));  // checked by reference()
    corners.push_back(positions_[size_t(index > 0 ? index - 1 : vertices_ + index)]);
  }
  std::vector<CornerTriangle> triangles;
  if (!triangulatePolygon(corners, &triangles))
    fail("a concave face of " + std::to_string(tokens.size()) +
         " corners; a face that is not convex may have at most " +
         std::to_string(kMaxConcaveFaceCorners) + " (split it into smaller faces)");
  for (const CornerTriangle& triangle : triangles) {
    out.text += 'f';
    for (const uint32_t corner : triangle) {
      out.text += ' ';
      out.text.append(tokens[corner].data(), tokens[corner].size());
    }
    out.text += '\n';
  }
}

}  // namespace

ObjScan scanObj(const std::string& text, const std::string& label) {
  ObjScan out;
  out.text.reserve(text.size());
  Scanner scanner(label);
  std::string_view rest(text);
  if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);  // UTF-8 byte order mark
  size_t number = 0;
  std::string joined;  // a statement continued over several lines, as one
  size_t joinedFrom = 0, joinedLines = 0;
  while (!rest.empty()) {
    const size_t end = lineEnd(rest);
    std::string_view line = rest.substr(0, end);
    ++number;
    const bool more = continues(line);
    if (more || joinedLines > 0) {
      if (joinedLines++ == 0) joinedFrom = number;
      if (more) line.remove_suffix(line.size() - line.find_last_not_of(" \t"));
      joined.append(line.data(), line.size());
      joined += ' ';
      if (!more || end == std::string_view::npos) {
        scanner.scanLine(joined, joinedFrom, out);
        out.text.append(joinedLines - 1, '\n');  // one output line per input line, as ever
        joined.clear();
        joinedLines = 0;
      }
    } else {
      scanner.scanLine(line, number, out);
    }
    if (end == std::string_view::npos) break;
    const bool crlf = rest[end] == '\r' && end + 1 < rest.size() && rest[end + 1] == '\n';
    rest.remove_prefix(end + (crlf ? 2 : 1));
  }
  return out;
}

}  // namespace candela
