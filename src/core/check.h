// Checks of internal invariants, in pbrt's style: MIRAGE_CHECK(x) and the comparisons
// MIRAGE_CHECK_EQ/NE/LT/LE/GT/GE(a, b), on in every build (the tests run the release build, so
// they run every check), for what the code assumes of itself, never for the user's input (that
// is an InputError naming the file and field). A failed check throws RuntimeError (exit 1)
// naming the source file and line, the condition and, for a comparison, both values:
// "internal error: src/core/supersample.cpp:41: check failed: a == b (120 vs. 119)".
// MIRAGE_DCHECK... are the same, compiled only into debug builds (hot loops).
#pragma once

#include <string>

#include <fmt/format.h>

namespace mirage::detail {

[[noreturn]] void checkFailed(const char* file, int line, const char* condition,
                              const std::string& values);

template <typename A, typename B>
[[noreturn]] void comparisonFailed(const char* file, int line, const char* condition, const A& a,
                                   const B& b) {
  checkFailed(file, line, condition, fmt::format("{} vs. {}", a, b));
}

}  // namespace mirage::detail

#define MIRAGE_CHECK(x)                                                  \
  do {                                                                   \
    if (!(x)) ::mirage::detail::checkFailed(__FILE__, __LINE__, #x, ""); \
  } while (false)

#define MIRAGE_CHECK_OP(a, op, b)                                                               \
  do {                                                                                          \
    const auto& mirage_check_a = (a);                                                           \
    const auto& mirage_check_b = (b);                                                           \
    if (!(mirage_check_a op mirage_check_b))                                                    \
      ::mirage::detail::comparisonFailed(__FILE__, __LINE__, #a " " #op " " #b, mirage_check_a, \
                                         mirage_check_b);                                       \
  } while (false)

#define MIRAGE_CHECK_EQ(a, b) MIRAGE_CHECK_OP(a, ==, b)
#define MIRAGE_CHECK_NE(a, b) MIRAGE_CHECK_OP(a, !=, b)
#define MIRAGE_CHECK_LT(a, b) MIRAGE_CHECK_OP(a, <, b)
#define MIRAGE_CHECK_LE(a, b) MIRAGE_CHECK_OP(a, <=, b)
#define MIRAGE_CHECK_GT(a, b) MIRAGE_CHECK_OP(a, >, b)
#define MIRAGE_CHECK_GE(a, b) MIRAGE_CHECK_OP(a, >=, b)

#ifdef NDEBUG
#define MIRAGE_DCHECK(x) \
  do {                   \
  } while (false)
#define MIRAGE_DCHECK_OP(a, op, b) \
  do {                             \
  } while (false)
#else
#define MIRAGE_DCHECK(x) MIRAGE_CHECK(x)
#define MIRAGE_DCHECK_OP(a, op, b) MIRAGE_CHECK_OP(a, op, b)
#endif
