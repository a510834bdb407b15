#include "methods/params.h"

#include <charconv>
#include <cmath>

#include "core/check.h"
#include "core/error.h"

namespace mirage {

namespace {

bool parseDouble(const std::string& text, double& out) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

bool parseInt(const std::string& text, long long& out) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end;
}

std::string formatNumber(double v) {
  return fmt::format("{:g}", v);
}

}  // namespace

ParamSpec ParamSpec::integer(std::string name, int min, int max, int def, std::string help) {
  return {std::move(name),     Type::kInt, double(min),    double(max),
          std::to_string(def), {},         std::move(help)};
}

ParamSpec ParamSpec::real(std::string name, double min, double max, double def, std::string help) {
  return {std::move(name), Type::kFloat, min, max, formatNumber(def), {}, std::move(help)};
}

ParamSpec ParamSpec::choice(std::string name, std::vector<std::string> choices, std::string def,
                            std::string help) {
  return {std::move(name),    Type::kChoice,  0, 0, std::move(def),
          std::move(choices), std::move(help)};
}

ParamSpec ParamSpec::text(std::string name, std::string range, std::string help, std::string def) {
  // A text parameter keeps its description of what it takes where a choice keeps its values.
  return {std::move(name), Type::kText, 0, 0, std::move(def), {std::move(range)}, std::move(help)};
}

std::string ParamSpec::rangeText() const {
  if (type == Type::kText) return choices.empty() ? "text" : choices.front();
  if (type == Type::kChoice) {
    std::string s;
    for (const auto& c : choices) s += (s.empty() ? "" : "|") + c;
    return s;
  }
  return formatNumber(min) + ".." + formatNumber(max);
}

void choiceMissing(const std::string& name, const std::string& value) {
  detail::checkFailed(__FILE__, __LINE__, "the table of choices holds the value",
                      fmt::format("--{} {}", name, value));
}

void checkParam(const ParamSpec& spec, const std::string& value) {
  auto fail = [&](const char* what) {
    throwInput("--{} {}: {}; allowed: {}", spec.name, value, what, spec.rangeText());
  };
  switch (spec.type) {
    case ParamSpec::Type::kInt: {
      long long v = 0;
      if (!parseInt(value, v)) fail("not an integer");
      if (double(v) < spec.min || double(v) > spec.max) fail("out of range");
      break;
    }
    case ParamSpec::Type::kFloat: {
      double v = 0;
      if (!parseDouble(value, v)) fail("not a number");
      if (v < spec.min || v > spec.max) fail("out of range");
      break;
    }
    case ParamSpec::Type::kChoice: {
      bool ok = false;
      for (const auto& c : spec.choices) ok = ok || c == value;
      if (!ok) fail("not one of the choices");
      break;
    }
    case ParamSpec::Type::kText:
      break;  // the method reads and checks it
  }
}

ParamValues ParamValues::validate(const std::vector<ParamSpec>& specs,
                                  const std::map<std::string, std::string>& given,
                                  const std::string& who) {
  ParamValues out;
  for (const ParamSpec& spec : specs) out.values_[spec.name] = spec.default_value;
  for (const auto& [name, value] : given) {
    const ParamSpec* spec = nullptr;
    for (const ParamSpec& s : specs)
      if (s.name == name) spec = &s;
    if (!spec) {
      std::string names;
      for (const ParamSpec& s : specs) names += (names.empty() ? "--" : ", --") + s.name;
      throwInput("{} has no parameter --{} (its parameters: {})", who, name,
                 names.empty() ? "none" : names);
    }
    checkParam(*spec, value);
    out.values_[name] = value;
  }
  return out;
}

int ParamValues::integer(const std::string& name) const {
  return std::stoi(text(name));
}
double ParamValues::real(const std::string& name) const {
  return std::stod(text(name));
}

bool ParamValues::on(const std::string& name) const {
  static constexpr Choice<bool> kOnOff[] = {{"on", true}, {"off", false}};
  return choice<bool>(name, kOnOff);
}

const std::string& ParamValues::text(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throwRuntime("parameter '{}' was not declared", name);
  return it->second;
}

}  // namespace mirage
