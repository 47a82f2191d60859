// Typed, path-aware access to a parsed JSON scene.
//
// A JsonValue is a JSON value plus where it sits: the scene file as the user named it and the JSON
// path ("spheres[2].radius"). Every accessor checks the value's type and range and, when the check
// fails, throws the one SceneError with a complete message:
//   "<file>: <path>: expected <what was expected>, got <the value, shortly>"
// A JsonObject also accounts for keys: unknown keys fail when it is opened (with a did-you-mean
// suggestion), keys that were present but never read fail in finish(). Keys beginning with '_' are
// comments and are invisible to both.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace candela {

using Json = nlohmann::json;

// Path of `key` inside the object at `base`: "camera.fov", or materials["red wall"] for keys that
// are not plain identifiers.
std::string memberPath(const std::string& base, const std::string& key);
// Path of element `index` of the array at `base`: "spheres[2]".
std::string elementPath(const std::string& base, size_t index);
// A JSON string literal, for names in messages: "abc" with quotes and escapes.
std::string quoted(const std::string& s);
// The value as shown after "got": -1, true, null, a string "abc", an array [1,2] (shortened).
std::string describeJson(const Json& value);
// Keys that begin with '_' are comments.
bool isCommentKey(const std::string& key);
// Throws SceneError "<file>: <path>: <message>" (no path part when path is empty).
[[noreturn]] void failAt(const std::string& file, const std::string& path,
                         const std::string& message);

class JsonValue {
 public:
  JsonValue(const Json& value, std::string file, std::string path)
      : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

  const Json& json() const { return *value_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

  [[noreturn]] void fail(const std::string& message) const;
  // Fails with "expected <expectation>, got <this value>".
  [[noreturn]] void failExpected(const std::string& expectation) const;

  // A finite number that fits a float; `expectation` names what is wanted when it is not one.
  float number(const std::string& expectation = "a number") const;
  float positiveNumber() const;     // > 0
  float nonNegativeNumber() const;  // >= 0
  // A number in [0, 1], worded by `expectation` ("a roughness in [0, 1]"); `orElse` (" or a
  // texture object") joins it where the value is not a number at all.
  float unitNumber(const std::string& expectation, const std::string& orElse = "") const;
  // An integer in [min, max] (integral floats such as 4.0 count); `expectation` words the range.
  uint64_t integer(uint64_t min, uint64_t max, const std::string& expectation) const;
  bool boolean() const;
  std::string string() const;
  // The index of this string among `options`; fails naming them, with a suggestion when close.
  size_t choice(const std::vector<std::string>& options) const;
  Vec3 vec3() const;    // [x, y, z]
  Vec3 colour() const;  // a grey scalar or [r, g, b], every component >= 0
  // The elements of an array; `expectation` names what is wanted when this is not an array.
  std::vector<JsonValue> elements(const std::string& expectation = "an array") const;
  // A rows x cols matrix given as an array of row arrays, row-major.
  std::vector<float> matrix(size_t rows, size_t cols) const;

 private:
  const Json* value_;
  std::string file_;
  std::string path_;
};

class JsonObject {
 public:
  // Fails unless `value` is an object ("expected <what>, got ...") and every key but comments is
  // one of `known`.
  JsonObject(const JsonValue& value, std::vector<std::string> known,
             const std::string& what = "an object");

  const JsonValue& value() const { return value_; }
  const std::string& path() const { return value_.path(); }
  [[noreturn]] void fail(const std::string& message) const { value_.fail(message); }

  bool has(const std::string& key) const;
  // The value under `key`, marked as used; nothing when absent.
  std::optional<JsonValue> get(const std::string& key);
  // The value under `key`, marked as used; fails when absent.
  JsonValue require(const std::string& key);
  // Fails at the key, with `reason`, when it is present.
  void reject(const std::string& key, const std::string& reason) const;
  // Fails when both keys are present: they say the same thing in two ways.
  void exclusive(const std::string& a, const std::string& b) const;
  // Fails on the first present key that was never read: a property nobody used is an error.
  void finish() const;

 private:
  JsonValue member(const std::string& key) const;

  JsonValue value_;
  std::vector<std::string> known_;
  std::set<std::string> used_;
};

}  // namespace candela
