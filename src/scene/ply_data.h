// Value readers for the data section of a PLY file, one per encoding, with the same interface so
// that the element loops in ply_reader.cpp are written once (as templates, without a virtual call
// per value: the full Stanford dragon has five million values).
//
// Every reader keeps the element being read (name, index, count) and reports problems with it:
// ASCII readers with the line number, binary readers with the byte offset.
#pragma once

#include <charconv>
#include <cstring>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/ply_header.h"

namespace mirage::ply {

// Where the reader is, for messages.
struct Position {
  const std::string* file = nullptr;
  const Element* element = nullptr;
  uint64_t index = 0;
};

// A value read for an integer property (a list length, an index): every PLY integer type is
// exact in a double, and a float property must hold a whole number that fits.
template <typename Reader>
int64_t wholeNumber(const Reader& reader, double v) {
  if (!(v >= -9.0e15 && v <= 9.0e15) || v != double(int64_t(v)))
    reader.fail(fmt::format("value {} is not an integer", v));
  return int64_t(v);
}

class AsciiReader {
 public:
  AsciiReader(const Position& at, std::string_view data, int first_line)
      : at_(at), p_(data.data()), end_(data.data() + data.size()), line_(first_line) {}

  // Moves to the next element's line (blank lines between elements are allowed).
  void beginElement() {
    while (p_ < end_ && isSpace(*p_)) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
    if (p_ == end_)
      throwInput("{}: line {}: the file ends before {} {} of {}", *at_.file, line_,
                 at_.element->name, at_.index, at_.element->count);
  }
  // The element must end at the end of its line.
  void endElement() {
    while (p_ < end_ && isBlank(*p_)) ++p_;
    if (p_ < end_ && *p_ != '\n')
      fail(fmt::format("has more values than its {} properties (the next is '{}')",
                       at_.element->properties.size(), peekToken()));
  }
  double real(Type) {
    std::string_view t = token();
    if (t.size() > 1 && t[0] == '+') t.remove_prefix(1);  // from_chars rejects a leading '+'
    double v = 0;
    auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec == std::errc::result_out_of_range) fail(fmt::format("value '{}' is out of range", t));
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(fmt::format("'{}' is not a number", t));
    return v;
  }
  int64_t integer(Type type) {
    if (!isInteger(type)) return wholeNumber(*this, real(type));
    std::string_view t = token();
    if (t.size() > 1 && t[0] == '+') t.remove_prefix(1);
    int64_t v = 0;
    auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(fmt::format("'{}' is not an integer", t));
    return v;
  }
  void skip(Type) { token(); }
  void skipList(Type count_type, Type item_type) {
    int64_t n = count(count_type);
    for (int64_t i = 0; i < n; ++i) skip(item_type);
  }
  int64_t count(Type type) {
    int64_t n = integer(type);
    if (n < 0) fail(fmt::format("list length {} is negative", n));
    return n;
  }
  // Whether only whitespace is left.
  bool atEnd() {
    while (p_ < end_ && isSpace(*p_)) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
    return p_ == end_;
  }
  int line() const { return line_; }

  [[noreturn]] void fail(const std::string& msg) const {
    throwInput("{}: line {}: {} {} of {} {}", *at_.file, line_, at_.element->name, at_.index,
               at_.element->count, msg);
  }

 private:
  static bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }
  static bool isSpace(char c) { return isBlank(c) || c == '\n'; }

  std::string_view token() {
    while (p_ < end_ && isBlank(*p_)) ++p_;
    if (p_ == end_ || *p_ == '\n')
      fail(
          fmt::format("has fewer values than its properties ({} properties; lists count their "
                      "length and items)",
                      at_.element->properties.size()));
    const char* start = p_;
    while (p_ < end_ && !isSpace(*p_)) ++p_;
    return {start, size_t(p_ - start)};
  }
  std::string peekToken() const {
    const char* e = p_;
    while (e < end_ && !isSpace(*e) && e - p_ < 40) ++e;
    return std::string(p_, e);
  }

  const Position& at_;
  const char* p_;
  const char* end_;
  int line_;
};

template <bool kSwap>
class BinaryReader {
 public:
  BinaryReader(const Position& at, std::string_view data, size_t offset)
      : at_(at), data_(data), pos_(offset), start_(offset) {}

  void beginElement() {}
  void endElement() {}
  double real(Type t) {
    return visitType(t, [this](auto v) { return double(this->template load<decltype(v)>()); });
  }
  int64_t integer(Type t) { return wholeNumber(*this, real(t)); }
  void skip(Type t) { skipBytes(typeSize(t)); }
  void skipList(Type count_type, Type item_type) {
    skipBytes(uint64_t(count(count_type)) * typeSize(item_type));
  }
  int64_t count(Type type) {
    int64_t n = integer(type);
    if (n < 0) fail(fmt::format("list length {} is negative", n));
    return n;
  }
  void skipBytes(uint64_t n) {
    if (n > data_.size() - pos_) truncated(n);
    pos_ += size_t(n);
  }
  size_t position() const { return pos_; }
  size_t remaining() const { return data_.size() - pos_; }

  [[noreturn]] void fail(const std::string& msg) const {
    throwInput("{}: byte {} of the data: {} {} of {} {}", *at_.file, pos_ - start_,
               at_.element->name, at_.index, at_.element->count, msg);
  }

 private:
  template <typename T>
  T load() {
    if (sizeof(T) > data_.size() - pos_) truncated(sizeof(T));
    char b[sizeof(T)];
    std::memcpy(b, data_.data() + pos_, sizeof(T));
    if constexpr (kSwap)
      for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    T v;
    std::memcpy(&v, b, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  [[noreturn]] void truncated(uint64_t wanted) const {
    fail(
        fmt::format("is cut off: {} more bytes were expected but the file ends {} bytes further "
                    "(truncated file or wrong element count)",
                    wanted, data_.size() - pos_));
  }

  const Position& at_;
  std::string_view data_;
  size_t pos_, start_;
};

}  // namespace mirage::ply
