#include "scene/scene_json_field.h"

#include <cmath>

namespace mirage::scene_json {

namespace {

const char* typeName(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "a number";
    default:
      return "an unsupported value";
  }
}

std::string formatNumber(double v) {
  return fmt::format("{}", v);
}

}  // namespace

std::string shortQuote(std::string_view text, size_t max_length) {
  std::string out = "'";
  for (size_t i = 0; i < text.size() && i < max_length; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    out += (c < 0x20 || c == 0x7f) ? '?' : char(c);
  }
  if (text.size() > max_length) out += "...";
  return out + "'";
}

Json parseDocument(const std::string& file, const std::string& text) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throwInput("{}: the file is empty (a scene file is a JSON object; see docs/scene-format.md)",
               file);
  // The callback sees each '{' and '[' with the depth of its parent before the container is
  // built, so a deep document is rejected before any deep structure exists.
  Json::parser_callback_t limit_depth = [&file](int depth, Json::parse_event_t event, Json&) {
    if ((event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) &&
        depth >= kMaxDepth)
      throwInput("{}: the JSON nests deeper than {} levels (a scene file needs fewer than 10)",
                 file, kMaxDepth);
    return true;
  };
  Json doc;
  try {
    doc = Json::parse(text, limit_depth, /*allow_exceptions=*/true, /*ignore_comments=*/false);
  } catch (const Json::exception& e) {  // parse_error, or out_of_range for numbers like 1e999
    // what() is "[json.exception.parse_error.101] parse error at line L, column C: ...; last
    // read: '<token>'": keep the part after the tag, cleaned and shortened.
    std::string_view what = e.what();
    if (size_t tag_end = what.find("] "); tag_end != std::string_view::npos)
      what.remove_prefix(tag_end + 2);
    std::string reason = shortQuote(what, 160);
    throwInput("{}: not valid JSON: {} (a scene file is a JSON object; see docs/scene-format.md)",
               file, reason.substr(1, reason.size() - 2));
  }
  if (!doc.is_object())
    throwInput(
        "{}: the top level is {}; a scene file is a JSON object {{...}} (see "
        "docs/scene-format.md)",
        file, typeName(doc));
  return doc;
}

bool Range::contains(double v) const {
  return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::text() const {
  bool no_lo = lo <= -1e299, no_hi = hi >= 1e299;
  if (no_lo && no_hi) return "any finite number";
  if (no_hi) return fmt::format("{} {}", lo_open ? ">" : ">=", formatNumber(lo));
  if (no_lo) return fmt::format("{} {}", hi_open ? "<" : "<=", formatNumber(hi));
  return fmt::format("{}{}, {}{}", lo_open ? "(" : "[", formatNumber(lo), formatNumber(hi),
                     hi_open ? ")" : "]");
}

std::string Field::where() const {
  return path_.empty() ? *file_ : *file_ + ": " + path_;
}

std::string Field::describe() const {
  const Json& v = *value_;
  if (v.is_number_integer()) return fmt::format("{}", v.get<int64_t>());
  if (v.is_number_unsigned()) return fmt::format("{}", v.get<uint64_t>());
  if (v.is_number_float()) return formatNumber(v.get<double>());
  if (v.is_string()) return shortQuote(v.get_ref<const std::string&>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_array()) return fmt::format("an array of {} elements", v.size());
  return typeName(v);
}

Field Field::child(std::string_view key, const Json& value) const {
  std::string k(key);
  return Field(*file_, value, path_.empty() ? k : path_ + "." + k);
}

void Field::requireObject(std::string_view what) const {
  if (!value_->is_object()) fail("must be {}, not {}", what, typeName(*value_));
}

bool Field::has(std::string_view key) const {
  requireObject("an object");
  return value_->contains(key);
}

Field Field::required(std::string_view key) const {
  requireObject("an object");
  auto it = value_->find(key);
  if (it == value_->end())
    throw InputError(fmt::format("{}: {}{}{} is required but missing", *file_, path_,
                                 path_.empty() ? "" : ".", key));
  return child(key, *it);
}

std::optional<Field> Field::optional(std::string_view key) const {
  requireObject("an object");
  auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return child(key, *it);
}

void Field::allowKeys(std::initializer_list<std::string_view> allowed,
                      std::string_view what) const {
  requireObject(fmt::format("{} (a JSON object)", what));
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    bool known = false;
    for (std::string_view a : allowed) known = known || it.key() == a;
    if (known) continue;
    std::string names;
    for (std::string_view a : allowed) names += (names.empty() ? "" : ", ") + std::string(a);
    std::string key = shortQuote(it.key());
    throw InputError(fmt::format("{}: {}{}{}: unknown field (allowed in {}: {})", *file_, path_,
                                 path_.empty() ? "" : ".", key.substr(1, key.size() - 2), what,
                                 names));
  }
}

std::vector<Field> Field::items() const {
  if (!value_->is_array()) fail("must be an array [...], not {}", typeName(*value_));
  std::vector<Field> out;
  out.reserve(value_->size());
  for (size_t i = 0; i < value_->size(); ++i)
    out.emplace_back(*file_, (*value_)[i], fmt::format("{}[{}]", path_, i));
  return out;
}

std::string Field::string() const {
  if (!value_->is_string()) fail("= {}: expected a string", describe());
  const std::string& s = value_->get_ref<const std::string&>();
  if (s.empty()) fail("is an empty string; expected a non-empty string");
  return s;
}

bool Field::boolean() const {
  if (!value_->is_boolean()) fail("= {}: expected true or false", describe());
  return value_->get<bool>();
}

float Field::number(const Range& range) const {
  if (!value_->is_number()) fail("= {}: expected a number ({})", describe(), range.text());
  double v = value_->get<double>();
  if (!range.contains(v)) {
    bool bounded = range.lo > -1e299 && range.hi < 1e299;
    if (bounded) fail("= {} is outside the allowed range {}", describe(), range.text());
    fail("= {} is not allowed: it must be {}", describe(), range.text());
  }
  // A finite double can still overflow float.
  if (!std::isfinite(float(v))) fail("= {} is too large for a float", describe());
  return float(v);
}

int Field::integer(int lo, int hi) const {
  if (!value_->is_number()) fail("= {}: expected an integer in {}..{}", describe(), lo, hi);
  double v = value_->get<double>();
  if (!std::isfinite(v) || v != std::floor(v))
    fail("= {}: expected an integer in {}..{}", describe(), lo, hi);
  if (v < double(lo) || v > double(hi))
    fail("= {} is outside the allowed range {}..{}", describe(), lo, hi);
  return int(v);
}

std::vector<float> Field::numbers(size_t count, const Range& range) const {
  if (!value_->is_array() || value_->size() != count)
    fail("= {}: expected an array of {} numbers ({})", describe(), count, range.text());
  std::vector<float> out;
  for (const Field& item : items()) out.push_back(item.number(range));
  return out;
}

vec2 Field::vector2(const Range& range) const {
  std::vector<float> v = numbers(2, range);
  return {v[0], v[1]};
}

vec3 Field::vector3(const Range& range) const {
  std::vector<float> v = numbers(3, range);
  return {v[0], v[1], v[2]};
}

std::string Field::stringOr(std::string_view key, std::string fallback) const {
  auto f = optional(key);
  return f ? f->string() : fallback;
}

bool Field::booleanOr(std::string_view key, bool fallback) const {
  auto f = optional(key);
  return f ? f->boolean() : fallback;
}

float Field::numberOr(std::string_view key, float fallback, const Range& range) const {
  auto f = optional(key);
  return f ? f->number(range) : fallback;
}

int Field::integerOr(std::string_view key, int fallback, int lo, int hi) const {
  auto f = optional(key);
  return f ? f->integer(lo, hi) : fallback;
}

vec3 Field::vector3Or(std::string_view key, vec3 fallback, const Range& range) const {
  auto f = optional(key);
  return f ? f->vector3(range) : fallback;
}

}  // namespace mirage::scene_json
