// The header of a PLY file (http://paulbourke.net/dataformats/ply/): format, elements and their
// properties. Parsed on its own so that every count can be checked against the limits and the
// bytes actually present before the reader allocates anything.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

namespace mirage::ply {

enum class Type : uint8_t { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

// The C++ type of each Type, in the enum's order.
using CppTypes = std::tuple<int8_t, uint8_t, int16_t, uint16_t, int32_t, uint32_t, float, double>;

// f(T{}) for the C++ type T that `t` names: the one place that maps the PLY types to C++'s.
template <typename F>
auto visitType(Type t, F&& f) {
  return [&]<size_t... I>(std::index_sequence<I...>) {
    decltype(f(int8_t{})) out{};
    ((size_t(t) == I ? void(out = f(std::tuple_element_t<I, CppTypes>{})) : void()), ...);
    return out;
  }
  (std::make_index_sequence<std::tuple_size_v<CppTypes>>{});
}

size_t typeSize(Type t);
bool isInteger(Type t);

enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct Property {
  std::string name;
  Type type = Type::kFloat32;  // the scalar's type, or a list's item type
  bool is_list = false;
  Type count_type = Type::kUint8;  // a list's length type
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
  int line = 0;  // header line, for messages

  // Index of the property called `name`, or -1.
  int find(std::string_view name) const;
  // The fewest bytes one element can take: binary sizes with empty lists, or for ASCII one
  // character and one separator per value.
  uint64_t minBytes(Format format) const;
};

struct Header {
  Format format = Format::kAscii;
  std::vector<Element> elements;
  size_t data_offset = 0;  // first byte after the end_header line
  int data_line = 0;       // line number of the first data line (ASCII messages)
  // Header lines read as comments though they are not `comment` lines (free text some exporters
  // write), one message each naming the line: the reader logs them as warnings.
  std::vector<std::string> warnings;

  const Element* find(std::string_view name) const;
};

// Parses the header of `bytes`; throws InputError naming `name`, the header line and what was
// expected. A line whose first word is no keyword is free text, read as a comment with a warning
// (as rply, plyfile and Blender's reader accept it), unless it could change the structure: a word
// one or two letters from a keyword ("elment", "end_headr": a misspelt declaration would shift
// every byte after it), a number or bytes that are not text (data: the end_header line is missing).
Header parseHeader(const std::string& name, std::string_view bytes);

// Throws InputError unless the `size` bytes of the file can hold the element counts the header
// declares (each element at least Element::minBytes).
void checkDataSize(const std::string& name, const Header& header, size_t size);

}  // namespace mirage::ply
