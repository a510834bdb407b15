// Method parameters: each method declares its parameters (name, type, range, default, help) so
// that the command line, the viewer and the reports treat every method's knobs alike, and every
// value is checked against its range with one message format.
#pragma once

#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/check.h"
#include "core/choices.h"

namespace mirage {

// A choice parameter's values and what each means to the method that reads it: a method lists
// its choices once, as a table (core/choices.h), for the spec (ParamSpec::choice) and for reading
// the value into its enum (ParamValues::choice), so that nothing compares the text with a literal:
//   constexpr Choice<Warper> kWarpers[] = {{"gpu", Warper::kGpu}, {"cpu", Warper::kCpu}};

struct ParamSpec {
  enum class Type { kInt, kFloat, kChoice, kText };

  std::string name;  // command-line name without dashes, e.g. "envmap-size"
  Type type = Type::kInt;
  double min = 0.0, max = 0.0;       // inclusive range (kInt, kFloat)
  std::string default_value;         // as text
  std::vector<std::string> choices;  // kChoice
  std::string help;

  static ParamSpec integer(std::string name, int min, int max, int def, std::string help);
  static ParamSpec real(std::string name, double min, double max, double def, std::string help);
  static ParamSpec choice(std::string name, std::vector<std::string> choices, std::string def,
                          std::string help);
  template <typename E>
  static ParamSpec choice(std::string name, std::span<const Choice<E>> choices, E def,
                          std::string help);
  // Free text that the method checks itself (mixed's assignment); `range` says what it takes.
  static ParamSpec text(std::string name, std::string range, std::string help,
                        std::string def = "");
  // "1..4096", "0..1e+06", "on|off", or a text parameter's `range`.
  std::string rangeText() const;
  bool operator==(const ParamSpec&) const = default;
};

// Validated parameter values by name, with defaults filled in.
class ParamValues {
 public:
  ParamValues() = default;
  // Checks `given` (name -> text) against `specs`: unknown names, bad numbers and values out of
  // range throw InputError naming the option and the allowed range.
  static ParamValues validate(const std::vector<ParamSpec>& specs,
                              const std::map<std::string, std::string>& given,
                              const std::string& who);

  int integer(const std::string& name) const;
  double real(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  // A choice parameter's value read through its table; a value the table lacks (the table and
  // the spec disagree: a bug) is an internal error (core/check.h) naming the parameter.
  template <typename E>
  E choice(const std::string& name, std::span<const Choice<E>> choices) const;
  // An on|off choice parameter.
  bool on(const std::string& name) const;
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  const std::map<std::string, std::string>& all() const { return values_; }

 private:
  std::map<std::string, std::string> values_;
};

// Checks one value against its spec; throws InputError("--name ...") on failure.
void checkParam(const ParamSpec& spec, const std::string& value);

[[noreturn]] void choiceMissing(const std::string& name, const std::string& value);

template <typename E>
ParamSpec ParamSpec::choice(std::string name, std::span<const Choice<E>> choices, E def,
                            std::string help) {
  std::vector<std::string> names;
  std::string def_name;
  for (const Choice<E>& c : choices) {
    names.emplace_back(c.name);
    if (c.value == def) def_name = c.name;
  }
  MIRAGE_CHECK(!def_name.empty());  // the default is one of the table's values
  return choice(std::move(name), std::move(names), std::move(def_name), std::move(help));
}

template <typename E>
E ParamValues::choice(const std::string& name, std::span<const Choice<E>> choices) const {
  const std::string& value = text(name);
  if (const std::optional<E> e = findChoice(choices, value)) return *e;
  choiceMissing(name, value);
}

}  // namespace mirage
