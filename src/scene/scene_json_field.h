// Reading a JSON scene file field by field. A Field is a value of the parsed document together
// with its file name and JSON path, so that every check can report "file: path = value is outside
// the allowed range [lo, hi]" without echoing the input back.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/math.h"

namespace mirage::scene_json {

using Json = nlohmann::json;

// Deeper documents are rejected while parsing: nothing in the format nests beyond 6 levels, and
// code that walks a JSON tree recursively must not meet an arbitrarily deep one.
inline constexpr int kMaxDepth = 64;
// Scene files describe scenes; geometry belongs in mesh files.
inline constexpr size_t kMaxFileBytes = size_t(64) << 20;

// Parses `text` (the content of `file`) into a JSON object; throws InputError naming the file on
// empty input, syntax errors, nesting deeper than kMaxDepth or a top level that is no object.
Json parseDocument(const std::string& file, const std::string& text);

// A closed, half-open or open numeric interval, printed the way messages show allowed values.
struct Range {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;

  static Range any() { return {}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range atLeast(double lo) { return {lo, 1e300, false, false}; }
  static Range above(double lo) { return {lo, 1e300, true, false}; }
  bool contains(double v) const;
  std::string text() const;
};

class Field {
 public:
  Field(const std::string& file, const Json& value, std::string path)
      : file_(&file), value_(&value), path_(std::move(path)) {}

  const std::string& file() const { return *file_; }
  const std::string& path() const { return path_; }
  const Json& json() const { return *value_; }
  // "file: path" (or just "file" for the top level), the prefix of every message.
  std::string where() const;

  // Throws InputError "file: path <message>".
  template <typename... Args>
  [[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) const {
    throw InputError(where() + " " + fmt::format(format, std::forward<Args>(args)...));
  }
  // A short description of the value for messages: a number, a truncated string, or its type.
  std::string describe() const;

  // Objects. Each requires this field to be an object.
  bool has(std::string_view key) const;
  Field required(std::string_view key) const;
  std::optional<Field> optional(std::string_view key) const;
  // Rejects keys outside `allowed`; `what` names the kind of object in the message.
  void allowKeys(std::initializer_list<std::string_view> allowed, std::string_view what) const;
  void requireObject(std::string_view what) const;

  // Arrays.
  std::vector<Field> items() const;

  // Scalars; each checks the type and the range.
  std::string string() const;  // non-empty
  bool boolean() const;
  float number(const Range& range = Range::any()) const;
  int integer(int lo, int hi) const;
  vec2 vector2(const Range& range = Range::any()) const;
  vec3 vector3(const Range& range = Range::any()) const;

  // Optional members with defaults.
  std::string stringOr(std::string_view key, std::string fallback) const;
  bool booleanOr(std::string_view key, bool fallback) const;
  float numberOr(std::string_view key, float fallback, const Range& range = Range::any()) const;
  int integerOr(std::string_view key, int fallback, int lo, int hi) const;
  vec3 vector3Or(std::string_view key, vec3 fallback, const Range& range = Range::any()) const;

 private:
  Field child(std::string_view key, const Json& value) const;
  std::vector<float> numbers(size_t count, const Range& range) const;

  const std::string* file_;
  const Json* value_;
  std::string path_;
};

// A user-supplied text (a key, a name) shortened and stripped of control characters, so that a
// message never carries a megabyte of input or terminal escapes.
std::string shortQuote(std::string_view text, size_t max_length = 48);

}  // namespace mirage::scene_json
