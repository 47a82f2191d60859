// Builds the JSON document through nlohmann's SAX interface, so that errors know where they are;
// see json_parse.h.
#include "scene/read/json_parse.h"

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "scene/scene_error.h"

namespace candela {
namespace {

// nlohmann's error id for a number that does not fit a double.
constexpr int kNumberOverflow = 406;

// Deeper than any scene needs (its deepest values sit about 6 levels down).
constexpr size_t kMaxJsonDepth = 64;

// A path of a deep nest, cut to its start and end.
std::string shortenedPath(const std::string& path) {
  return path.size() <= 120 ? path : path.substr(0, 56) + "..." + path.substr(path.size() - 56);
}

class DomBuilder : public nlohmann::json_sax<Json> {
 public:
  DomBuilder(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  Json& root() { return root_; }

  bool null() override { return put(Json(nullptr)); }
  bool boolean(bool value) override { return put(Json(value)); }
  bool number_integer(number_integer_t value) override { return put(Json(value)); }
  bool number_unsigned(number_unsigned_t value) override { return put(Json(value)); }
  bool number_float(number_float_t value, const string_t&) override { return put(Json(value)); }
  bool string(string_t& value) override { return put(Json(std::move(value))); }
  bool binary(binary_t& value) override { return put(Json::binary(std::move(value))); }

  bool start_object(std::size_t) override { return open(Json::object()); }
  bool start_array(std::size_t) override { return open(Json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& key) override {
    Frame& frame = stack_.back();
    if (!isCommentKey(key) && !frame.keys.insert(key).second)
      failAt(file_, memberPath(frame.path, key),
             "duplicate key, each key may appear once per object");
    frame.key = std::move(key);
    return true;
  }

  bool parse_error(std::size_t position, const std::string& lastToken,
                   const Json::exception& error) override {
    if (error.id == kNumberOverflow)
      failAt(file_, slotPath(), "expected a finite number, got " + lastToken);
    throw SceneError(file_ + ":" + lineAndColumn(position) +
                     ": invalid JSON: " + reason(error, lastToken));
  }

 private:
  struct Frame {
    Json* container;
    std::string path;
    std::string key;  // objects: the key whose value comes next
    std::set<std::string> keys;
  };

  // The JSON path of the value that comes next.
  std::string slotPath() const {
    if (stack_.empty()) return "";
    const Frame& frame = stack_.back();
    if (frame.container->is_array()) return elementPath(frame.path, frame.container->size());
    return memberPath(frame.path, frame.key);
  }

  Json* insert(Json&& value) {
    if (stack_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Frame& frame = stack_.back();
    if (frame.container->is_array()) {
      frame.container->push_back(std::move(value));
      return &frame.container->back();
    }
    Json& slot = (*frame.container)[frame.key];
    slot = std::move(value);
    return &slot;
  }

  bool put(Json&& value) {
    insert(std::move(value));
    return true;
  }

  bool open(Json&& container) {
    // Each open container keeps its path: bounding the depth bounds that memory (it grew with the
    // square of the depth) as well as the work of every message.
    if (stack_.size() >= kMaxJsonDepth)
      failAt(file_, shortenedPath(slotPath()),
             "nested deeper than " + std::to_string(kMaxJsonDepth) +
                 " levels; a scene never needs that");
    std::string path = slotPath();
    // Containers on the stack stay put: an array only grows again after its last element closed.
    Json* inserted = insert(std::move(container));
    stack_.push_back(Frame{inserted, std::move(path), {}, {}});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  // nlohmann reports the count of bytes read; the offending byte is the last of them.
  std::string lineAndColumn(std::size_t bytesRead) const {
    const size_t offset = std::min(bytesRead > 0 ? bytesRead - 1 : 0, text_.size());
    const size_t line = 1 + std::count(text_.begin(), text_.begin() + offset, '\n');
    const size_t lineStart = offset == 0 ? std::string::npos : text_.rfind('\n', offset - 1);
    const size_t column = lineStart == std::string::npos ? offset + 1 : offset - lineStart;
    return std::to_string(line) + ":" + std::to_string(column);
  }

  // The reason part of "[json.exception.parse_error.101] parse error at line 1, column 2: ...",
  // with a long "last read: '...'" token cut to its end, where the fault is.
  static std::string reason(const Json::exception& error, const std::string& lastToken) {
    const std::string what = error.what();
    const size_t start = what.find("parse error");
    const size_t colon = start == std::string::npos ? std::string::npos : what.find(": ", start);
    std::string text = colon != std::string::npos ? what.substr(colon + 2) : what;
    const size_t kept = 20;
    const std::string quotedToken = "last read: '" + lastToken + "'";
    const size_t at = text.find(quotedToken);
    if (lastToken.size() > kept && at != std::string::npos) {
      size_t cut = lastToken.size() - kept;
      while (cut < lastToken.size() && (static_cast<unsigned char>(lastToken[cut]) & 0xC0) == 0x80)
        ++cut;
      text.replace(at, quotedToken.size(), "last read: '..." + lastToken.substr(cut) + "'");
    }
    return text;
  }

  const std::string& text_;
  const std::string& file_;
  Json root_;
  std::vector<Frame> stack_;
};

}  // namespace

Json parseJson(const std::string& text, const std::string& file) {
  DomBuilder builder(text, file);
  Json::sax_parse(text, &builder, Json::input_format_t::json, /*strict=*/true,
                  /*ignore_comments=*/false);
  return std::move(builder.root());
}

}  // namespace candela
