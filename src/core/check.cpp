#include "core/check.h"

#include <string_view>

#include "core/error.h"

namespace mirage::detail {

void checkFailed(const char* file, int line, const char* condition, const std::string& values) {
  // The path from src/ on: __FILE__ is absolute in out-of-tree builds.
  std::string_view path(file);
  if (size_t src = path.rfind("/src/"); src != std::string_view::npos) path.remove_prefix(src + 1);
  throwRuntime("internal error: {}:{}: check failed: {}{}", path, line, condition,
               values.empty() ? "" : " (" + values + ")");
}

}  // namespace mirage::detail
