// Path-aware JSON access with complete error messages; see json_reader.h.
#include "scene/read/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>

#include "scene/read/did_you_mean.h"
#include "scene/scene_error.h"

namespace candela {

static bool isIdentifier(const std::string& key) {
  if (key.empty()) return false;
  for (char c : key)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  return true;
}

std::string memberPath(const std::string& base, const std::string& key) {
  // Paths are for messages: a key longer than any name is shown by its start.
  constexpr size_t kLongestShown = 64;
  if (key.size() > kLongestShown) {
    size_t cut = kLongestShown;
    while (cut > 0 && (static_cast<unsigned char>(key[cut]) & 0xC0) == 0x80) --cut;
    return base + "[" + quoted(key.substr(0, cut)) + "...]";
  }
  if (!isIdentifier(key)) return base + "[" + quoted(key) + "]";
  return base.empty() ? key : base + "." + key;
}

std::string elementPath(const std::string& base, size_t index) {
  return base + "[" + std::to_string(index) + "]";
}

std::string quoted(const std::string& s) { return Json(s).dump(); }

// Cuts long text at a UTF-8 character boundary so messages stay short and valid.
static std::string shortened(const std::string& text) {
  const size_t limit = 60;
  if (text.size() <= limit) return text;
  size_t cut = limit - 3;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "...";
}

std::string describeJson(const Json& value) {
  const std::string text = shortened(value.dump());
  if (value.is_string()) return "a string " + text;
  if (value.is_array()) return "an array " + text;
  if (value.is_object()) return "an object " + text;
  return text;
}

bool isCommentKey(const std::string& key) { return !key.empty() && key[0] == '_'; }

void failAt(const std::string& file, const std::string& path, const std::string& message) {
  throw SceneError(file + ": " + (path.empty() ? "" : path + ": ") + message);
}

void JsonValue::fail(const std::string& message) const { failAt(file_, path_, message); }

void JsonValue::failExpected(const std::string& expectation) const {
  fail("expected " + expectation + ", got " + describeJson(json()));
}

float JsonValue::number(const std::string& expectation) const {
  if (!json().is_number()) failExpected(expectation);
  const double value = json().get<double>();
  // The parser refuses numbers that overflow a double; these would overflow the float we store.
  if (!(std::fabs(value) <= FLT_MAX)) failExpected("a finite number within single precision");
  return static_cast<float>(value);
}

float JsonValue::positiveNumber() const {
  const float value = number("a positive number");
  if (!(value > 0)) failExpected("a positive number");
  return value;
}

float JsonValue::nonNegativeNumber() const {
  const float value = number("a non-negative number");
  if (!(value >= 0)) failExpected("a non-negative number");
  return value;
}

float JsonValue::unitNumber(const std::string& expectation, const std::string& orElse) const {
  const float value = number(expectation + orElse);
  if (!(value >= 0.0f && value <= 1.0f)) failExpected(expectation);
  return value;
}

uint64_t JsonValue::integer(uint64_t min, uint64_t max, const std::string& expectation) const {
  uint64_t value = 0;
  if (json().is_number_unsigned()) {
    value = json().get<uint64_t>();
  } else if (json().is_number_float()) {
    const double d = json().get<double>();
    if (!(d >= 0 && d < 18446744073709551616.0 && d == std::floor(d))) failExpected(expectation);
    value = static_cast<uint64_t>(d);
  } else {
    failExpected(expectation);  // not a number, or a negative integer
  }
  if (value > max) failExpected(expectation + " of at most " + std::to_string(max));
  if (value < min) failExpected(expectation);
  return value;
}

bool JsonValue::boolean() const {
  if (!json().is_boolean()) failExpected("true or false");
  return json().get<bool>();
}

std::string JsonValue::string() const {
  if (!json().is_string()) failExpected("a string");
  return json().get<std::string>();
}

size_t JsonValue::choice(const std::vector<std::string>& options) const {
  if (json().is_string()) {
    const std::string& text = json().get_ref<const std::string&>();
    for (size_t i = 0; i < options.size(); ++i)
      if (options[i] == text) return i;
  }
  std::string expectation;
  if (options.size() == 1) {
    expectation = quoted(options[0]);
  } else if (options.size() == 2) {
    expectation = quoted(options[0]) + " or " + quoted(options[1]);
  } else {
    for (const std::string& option : options)
      expectation += (expectation.empty() ? "one of " : ", ") + quoted(option);
  }
  const std::string suggestion =
      json().is_string() ? closestMatch(json().get<std::string>(), options) : "";
  if (suggestion.empty()) failExpected(expectation);
  fail("expected " + expectation + ", got " + describeJson(json()) + ", did you mean " +
       quoted(suggestion) + "?");
}

std::vector<JsonValue> JsonValue::elements(const std::string& expectation) const {
  if (!json().is_array()) failExpected(expectation);
  std::vector<JsonValue> result;
  result.reserve(json().size());
  for (size_t i = 0; i < json().size(); ++i)
    result.emplace_back(json()[i], file_, elementPath(path_, i));
  return result;
}

Vec3 JsonValue::vec3() const {
  const std::string expectation = "an array of 3 numbers";
  if (!json().is_array() || json().size() != 3) failExpected(expectation);
  const std::vector<JsonValue> e = elements();
  return {e[0].number(), e[1].number(), e[2].number()};
}

Vec3 JsonValue::colour() const {
  if (json().is_number()) return Vec3(nonNegativeNumber());
  // Colours that take textures are read by readTexturedColour (texture_reader.h) instead.
  if (json().is_object() && (json().contains("texture") || json().contains("checkerboard")))
    fail("a texture on a field that takes none (expected a number or an array of 3 numbers)");
  if (!json().is_array() || json().size() != 3)
    failExpected("a colour (a number or an array of 3 numbers)");
  const std::vector<JsonValue> e = elements();
  return {e[0].nonNegativeNumber(), e[1].nonNegativeNumber(), e[2].nonNegativeNumber()};
}

std::vector<float> JsonValue::matrix(size_t rows, size_t cols) const {
  const std::string r = std::to_string(rows), c = std::to_string(cols);
  if (!json().is_array() || json().size() != rows)
    failExpected("a " + r + "x" + c + " matrix (an array of " + r + " rows of " + c + " numbers)");
  std::vector<float> result;
  for (const JsonValue& row : elements()) {
    if (!row.json().is_array() || row.json().size() != cols)
      row.failExpected("a row of " + c + " numbers");
    for (const JsonValue& entry : row.elements()) result.push_back(entry.number());
  }
  return result;
}

JsonObject::JsonObject(const JsonValue& value, std::vector<std::string> known,
                       const std::string& what)
    : value_(value), known_(std::move(known)) {
  if (!value_.json().is_object()) value_.failExpected(what);
  for (const auto& item : value_.json().items()) {
    const std::string& key = item.key();
    if (isCommentKey(key) || std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
    const std::string suggestion = closestMatch(key, known_);
    if (!suggestion.empty())
      member(key).fail("unknown key, did you mean " + quoted(suggestion) + "?");
    std::string list;
    for (const std::string& k : known_) list += (list.empty() ? "" : ", ") + quoted(k);
    member(key).fail("unknown key, expected one of " + list);
  }
}

JsonValue JsonObject::member(const std::string& key) const {
  return JsonValue(value_.json().at(key), value_.file(), memberPath(value_.path(), key));
}

bool JsonObject::has(const std::string& key) const { return value_.json().contains(key); }

std::optional<JsonValue> JsonObject::get(const std::string& key) {
  if (!has(key)) return std::nullopt;
  used_.insert(key);
  return member(key);
}

JsonValue JsonObject::require(const std::string& key) {
  if (!has(key)) fail("missing required key " + quoted(key));
  used_.insert(key);
  return member(key);
}

void JsonObject::reject(const std::string& key, const std::string& reason) const {
  if (has(key)) member(key).fail(reason);
}

void JsonObject::exclusive(const std::string& a, const std::string& b) const {
  if (has(a) && has(b)) fail("expected either " + quoted(a) + " or " + quoted(b) + ", got both");
}

void JsonObject::finish() const {
  for (const auto& item : value_.json().items())
    if (!isCommentKey(item.key()) && used_.count(item.key()) == 0)
      member(item.key()).fail("not used here");
}

}  // namespace candela
