// Shader sources: found among the files embedded in the binary (or, for live editing, under
// the directory named by MIRAGE_SHADER_DIR), with `#include "..."` resolved textually, include-
// once, relative to the including file and then to src/. Every file gets a `#line` directive
// with its own source-string number, so compile errors can name the file and line.
#pragma once

#include <string>
#include <vector>

namespace mirage::gpu {

struct ShaderSource {
  std::string text;                // ready for glShaderSource
  std::vector<std::string> files;  // files[i] is the path of GLSL source-string number i
};

// `defines` are lines like "NAME" or "NAME VALUE", emitted as #define after #version.
ShaderSource loadShaderSource(const std::string& path,
                              const std::vector<std::string>& defines = {});

// Rewrites a driver's compile log so that "S:L" / "S(L)" locations name files.
std::string annotateShaderLog(const std::string& log, const std::vector<std::string>& files);

// The text of a shader file (embedded, or from MIRAGE_SHADER_DIR); throws if there is none.
std::string shaderFile(const std::string& path);

}  // namespace mirage::gpu
