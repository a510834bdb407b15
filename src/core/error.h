// Errors that reach the user. Each kind maps to one exit code of the `mirage` tool, so that
// scripts can tell bad input (2) from a missing OpenGL 4.5 driver (3) from a failure of ours (1).
#pragma once

#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace mirage {

enum class ExitCode : int {
  kOk = 0,
  kFailure = 1,   // a bug or an environment problem that is not the user's input
  kBadInput = 2,  // bad command line, scene file, mesh, image or parameter
  kNoOpenGL = 3,  // no OpenGL 4.5 driver could be found
};

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

// Bad user input: the message names the file, the field and the allowed values.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(ExitCode::kBadInput, message) {}
};

// No usable OpenGL 4.5 context.
class NoOpenGLError : public Error {
 public:
  explicit NoOpenGLError(const std::string& message) : Error(ExitCode::kNoOpenGL, message) {}
};

// Anything else: a driver failure, an I/O error on output, a bug of ours.
class RuntimeError : public Error {
 public:
  explicit RuntimeError(const std::string& message) : Error(ExitCode::kFailure, message) {}
};

// The OpenGL driver refused what a method asked for within its rights: a texture, buffer or
// storage block beyond a driver limit, GPU memory exhausted, a shader's loops beyond what the
// driver lets them run (gpu/loop_budget.h). The frame renderer answers it by falling back to
// `envmap` with a warning (methods/method_guard.h).
class GpuError : public RuntimeError {
 public:
  explicit GpuError(const std::string& message) : RuntimeError(message) {}
};

// A program of mirage's that does not compile or link: a bug of ours, never a driver limit to
// fall back from (exit 1, the program named with the driver's log).
class ShaderError : public RuntimeError {
 public:
  explicit ShaderError(const std::string& message) : RuntimeError(message) {}
};

template <typename... Args>
[[noreturn]] void throwInput(fmt::format_string<Args...> format, Args&&... args) {
  throw InputError(fmt::format(format, std::forward<Args>(args)...));
}

template <typename... Args>
[[noreturn]] void throwRuntime(fmt::format_string<Args...> format, Args&&... args) {
  throw RuntimeError(fmt::format(format, std::forward<Args>(args)...));
}

template <typename... Args>
[[noreturn]] void throwGpu(fmt::format_string<Args...> format, Args&&... args) {
  throw GpuError(fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace mirage
