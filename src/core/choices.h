// An enum's values with their names, written once as a table and read both ways: a name for a
// value (what a report or the panel shows), a value for a name (what an option gives):
//   constexpr Choice<ToneMap> kToneMaps[] = {{"clamp", ToneMap::kClamp}, ...};
// Method parameters build their specs from such tables (methods/params.h).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/check.h"

namespace mirage {

template <typename E>
struct Choice {
  const char* name;
  E value;
};

// The name of `value`; a value missing from its table is an internal error.
template <typename E>
const char* choiceName(std::span<const Choice<E>> table, E value) {
  for (const Choice<E>& c : table)
    if (c.value == value) return c.name;
  MIRAGE_CHECK(!"a value missing from its table of names");
  return "";
}

// The value named `name`, or nothing.
template <typename E>
std::optional<E> findChoice(std::span<const Choice<E>> table, std::string_view name) {
  for (const Choice<E>& c : table)
    if (name == c.name) return c.value;
  return std::nullopt;
}

// The names, joined: "clamp, reinhard, aces" (or with another separator: "off|split|flip").
template <typename E>
std::string choiceNames(std::span<const Choice<E>> table, std::string_view separator = ", ") {
  std::string out;
  for (const Choice<E>& c : table) {
    if (!out.empty()) out += separator;
    out += c.name;
  }
  return out;
}

}  // namespace mirage
