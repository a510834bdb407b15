#include "scene/ply_header.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.h"

namespace mirage::ply {

namespace {

std::optional<Type> parseType(std::string_view s) {
  // The names of the original specification, then the sized names most writers use today.
  static constexpr std::pair<std::string_view, Type> kNames[] = {
      {"char", Type::kInt8},      {"uchar", Type::kUint8},    {"short", Type::kInt16},
      {"ushort", Type::kUint16},  {"int", Type::kInt32},      {"uint", Type::kUint32},
      {"float", Type::kFloat32},  {"double", Type::kFloat64}, {"int8", Type::kInt8},
      {"uint8", Type::kUint8},    {"int16", Type::kInt16},    {"uint16", Type::kUint16},
      {"int32", Type::kInt32},    {"uint32", Type::kUint32},  {"float32", Type::kFloat32},
      {"float64", Type::kFloat64}};
  for (const auto& [n, t] : kNames)
    if (n == s) return t;
  return std::nullopt;
}

constexpr const char* kTypeNames =
    "char/int8, uchar/uint8, short/int16, ushort/uint16, int/int32, uint/uint32, float/float32, "
    "double/float64";

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

constexpr std::string_view kKeywords[] = {"format",     "element", "property",
                                          "end_header", "comment", "obj_info"};

// Levenshtein distance, stopping early past `limit` (the words compared are short).
int editDistance(std::string_view a, std::string_view b, int limit) {
  if (int(a.size()) - int(b.size()) > limit || int(b.size()) - int(a.size()) > limit)
    return limit + 1;
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = int(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = int(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The keyword `word` looks like a misspelling of, or nullopt.
std::optional<std::string_view> nearKeyword(std::string_view word) {
  for (std::string_view k : kKeywords)
    if (editDistance(word, k, 2) <= 2) return k;
  return std::nullopt;
}

bool looksNumeric(std::string_view word) {
  const char c = word.empty() ? ' ' : word[0];
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
}

bool isText(std::string_view line) {
  for (unsigned char c : line)
    if ((c < 0x20 && c != '\t') || c == 0x7f) return false;
  return true;
}

}  // namespace

size_t typeSize(Type t) {
  return visitType(t, [](auto v) { return sizeof(v); });
}

bool isInteger(Type t) {
  return visitType(t, [](auto v) { return std::is_integral_v<decltype(v)>; });
}

int Element::find(std::string_view property) const {
  for (size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property) return int(i);
  return -1;
}

uint64_t Element::minBytes(Format format) const {
  uint64_t n = 0;
  for (const Property& p : properties)
    n += format == Format::kAscii ? 2 : typeSize(p.is_list ? p.count_type : p.type);
  return n;
}

const Element* Header::find(std::string_view element) const {
  for (const Element& e : elements)
    if (e.name == element) return &e;
  return nullptr;
}

namespace {

// The header's lines read one at a time, each keyword by its own member.
class HeaderParser {
 public:
  HeaderParser(const std::string& name, std::string_view bytes) : name_(name), bytes_(bytes) {}

  Header parse() {
    for (;;) {
      const std::string_view line = nextLine();
      if (line_no_ == 1) {
        if (line != "ply") throwInput("{}: not a PLY file (the first line must be 'ply')", name_);
        continue;
      }
      std::vector<std::string_view> t = tokens(line);
      if (t.empty()) continue;
      std::string_view key = t[0];
      if (key == "comment" || key == "obj_info") continue;
      if (key == "end_header") break;
      if (key == "format")
        format(t);
      else if (key == "element")
        element(t);
      else if (key == "property")
        property(t);
      else
        unknownLine(key, line);
    }
    if (!have_format_) throwInput("{}: the PLY header has no 'format' line", name_);
    h_.data_offset = pos_;
    h_.data_line = line_no_ + 1;
    return std::move(h_);
  }

 private:
  [[noreturn]] void fail(std::string_view msg) const {
    throwInput("{}: line {}: {}", name_, line_no_, msg);
  }

  // The next line without its end of line; the end of the file before end_header is an error.
  std::string_view nextLine() {
    if (pos_ >= bytes_.size()) {
      if (line_no_ == 0) throwInput("{}: empty file (expected a PLY header)", name_);
      throwInput("{}: the PLY header has no end_header line (the file ends at line {}{})", name_,
                 line_no_,
                 first_free_text_
                     ? fmt::format("; lines from {} on were read as free text", first_free_text_)
                     : std::string());
    }
    size_t eol = bytes_.find('\n', pos_);
    size_t next = eol == std::string_view::npos ? bytes_.size() : eol + 1;
    std::string_view line = bytes_.substr(pos_, next - pos_);
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
    pos_ = next;
    ++line_no_;
    return line;
  }

  void format(const std::vector<std::string_view>& t) {
    if (have_format_) fail("a second 'format' line");
    if (t.size() != 3) fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
    if (t[1] == "ascii")
      h_.format = Format::kAscii;
    else if (t[1] == "binary_little_endian")
      h_.format = Format::kBinaryLittleEndian;
    else if (t[1] == "binary_big_endian")
      h_.format = Format::kBinaryBigEndian;
    else
      fail(
          fmt::format("unknown format '{}' (expected ascii, binary_little_endian or "
                      "binary_big_endian)",
                      t[1]));
    if (t[2] != "1.0") fail(fmt::format("unsupported PLY version '{}' (expected 1.0)", t[2]));
    have_format_ = true;
  }

  void element(const std::vector<std::string_view>& t) {
    if (t.size() != 3) fail("expected 'element <name> <count>'");
    Element e;
    e.name = std::string(t[1]);
    e.line = line_no_;
    auto r = std::from_chars(t[2].data(), t[2].data() + t[2].size(), e.count);
    if (r.ec != std::errc() || r.ptr != t[2].data() + t[2].size())
      fail(fmt::format("element {}: count '{}' is not a number in 0..{}", t[1], t[2], UINT64_MAX));
    if (h_.find(e.name)) fail(fmt::format("element '{}' is declared twice", t[1]));
    h_.elements.push_back(std::move(e));
  }

  void property(const std::vector<std::string_view>& t) {
    if (h_.elements.empty()) fail("a property before any element");
    Property p;
    if (t.size() == 5 && t[1] == "list") {
      auto count_type = parseType(t[2]);
      auto item_type = parseType(t[3]);
      if (!count_type || !item_type)
        fail(fmt::format("unknown type '{}' (expected one of {})", count_type ? t[3] : t[2],
                         kTypeNames));
      if (!isInteger(*count_type))
        fail(fmt::format("list {}: the length type {} must be an integer type", t[4], t[2]));
      p.is_list = true;
      p.count_type = *count_type;
      p.type = *item_type;
      p.name = std::string(t[4]);
    } else if (t.size() == 3 && t[1] != "list") {
      auto type = parseType(t[1]);
      if (!type) fail(fmt::format("unknown type '{}' (expected one of {})", t[1], kTypeNames));
      p.type = *type;
      p.name = std::string(t[2]);
    } else {
      fail("expected 'property <type> <name>' or 'property list <type> <type> <name>'");
    }
    h_.elements.back().properties.push_back(std::move(p));
  }

  // A line of no keyword: a misspelt keyword, binary or numeric data are errors; free text is
  // read as a comment, with a warning.
  void unknownLine(std::string_view key, std::string_view line) {
    const std::string shown(key.substr(0, 40));
    if (const auto near = nearKeyword(key))
      fail(
          fmt::format("unknown header keyword '{}' (a misspelt '{}'? expected format, element, "
                      "property, comment, obj_info or end_header)",
                      shown, *near));
    if (!isText(line))
      fail("a header line holds bytes that are not text (binary data before end_header?)");
    if (looksNumeric(key))
      fail(fmt::format("'{}' is a number, not a header keyword (data before end_header?)", shown));
    if (!first_free_text_) first_free_text_ = line_no_;
    h_.warnings.push_back(
        fmt::format("{}: line {}: '{}' is not a header keyword; the line is read as a comment",
                    name_, line_no_, line.substr(line.find_first_not_of(" \t")).substr(0, 60)));
  }

  const std::string& name_;
  std::string_view bytes_;
  Header h_;
  bool have_format_ = false;
  int line_no_ = 0;
  int first_free_text_ = 0;  // the first line read as free text, for the missing end_header
  size_t pos_ = 0;
};

}  // namespace

Header parseHeader(const std::string& name, std::string_view bytes) {
  return HeaderParser(name, bytes).parse();
}

void checkDataSize(const std::string& name, const Header& h, size_t size) {
  const size_t pos = h.data_offset;
  // Fail fast on counts the data cannot hold: a 200-byte file claiming 10^12 vertices is refused
  // here, before anything is allocated or parsed.
  uint64_t available = size - pos;
  if (h.format == Format::kAscii) ++available;  // the last line may lack its newline
  uint64_t needed = 0;
  for (const Element& e : h.elements) {
    uint64_t each = e.minBytes(h.format);
    if (each == 0) continue;
    uint64_t left = available - needed;
    if (e.count > left / each)
      throwInput(
          "{}: line {}: element {} declares {} elements of at least {} bytes each, but only "
          "{} bytes of data follow the header (truncated file or wrong count)",
          name, e.line, e.name, e.count, each, size - pos);
    needed += e.count * each;
  }
}

}  // namespace mirage::ply
