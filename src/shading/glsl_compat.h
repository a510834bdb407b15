// The thin layer that lets one header compile both as C++ (with glm) and as GLSL 4.50.
//
// Rules for shared headers (docs/architecture.md, "One shading model"):
//  - wrap the code in SHARED_BEGIN / SHARED_END and prefix functions with SHARED_FN;
//  - pass by value; use SHARED_OUT(T) / SHARED_INOUT(T) for out and inout parameters;
//  - write float literals with an f suffix (1.0f): GLSL accepts it, and glm needs it;
//  - no struct constructors, arrays, samplers or overloads that differ between the languages;
//  - constants that must be visible to both as layout bindings are #defines.
#ifndef MIRAGE_SHADING_GLSL_COMPAT_H
#define MIRAGE_SHADING_GLSL_COMPAT_H

#ifdef MIRAGE_GLSL

#define SHARED_BEGIN
#define SHARED_END
#define SHARED_FN
#define SHARED_CONST const
#define SHARED_OUT(T) out T
#define SHARED_INOUT(T) inout T

#else  // C++

// Angle brackets: the GLSL include resolver skips them (C++-only includes).
#include <core/math.h>

#define SHARED_BEGIN          \
  namespace mirage::shading { \
  using namespace glm;        \
  using uint = unsigned int;
#define SHARED_END }
#define SHARED_FN inline
#define SHARED_CONST inline constexpr
#define SHARED_OUT(T) T&
#define SHARED_INOUT(T) T&

#endif  // MIRAGE_GLSL
#endif  // MIRAGE_SHADING_GLSL_COMPAT_H
