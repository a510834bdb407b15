#include "gpu/shader_source.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/embedded_files.h"
#include "core/error.h"

namespace mirage::gpu {

namespace {

std::string trimLeft(const std::string& s) {
  size_t i = s.find_first_not_of(" \t");
  return i == std::string::npos ? std::string() : s.substr(i);
}

bool shaderFileExists(const std::string& path) {
  for (const auto& f : embedded::files())
    if (path == f.path) return true;
  return false;
}

void expand(const std::string& path, ShaderSource& out, std::set<std::string>& seen, int depth) {
  if (depth > 32) throwRuntime("shader include depth exceeds 32 at '{}'", path);
  if (!seen.insert(path).second) return;  // include once
  const int index = int(out.files.size());
  out.files.push_back(path);
  out.text += "#line 1 " + std::to_string(index) + "\n";
  std::istringstream lines(shaderFile(path));
  std::string line;
  int number = 0;
  const std::string dir = std::filesystem::path(path).parent_path().string();
  while (std::getline(lines, line)) {
    ++number;
    std::string t = trimLeft(line);
    if (t.rfind("#include", 0) != 0) {
      out.text += line + "\n";
      continue;
    }
    size_t open = t.find_first_of("\"<", 8);
    if (open == std::string::npos) throwRuntime("{}:{}: malformed #include", path, number);
    if (t[open] == '<') {  // a C++-only include of a shared header: not for GLSL
      out.text += "\n";
      continue;
    }
    size_t close = t.find('"', open + 1);
    if (close == std::string::npos) throwRuntime("{}:{}: malformed #include", path, number);
    std::string name = t.substr(open + 1, close - open - 1);
    std::string relative =
        dir.empty() ? name : (std::filesystem::path(dir) / name).lexically_normal().string();
    std::string resolved = shaderFileExists(relative) ? relative : name;
    if (!shaderFileExists(resolved))
      throwRuntime("{}:{}: included file '{}' is not among the shader sources", path, number, name);
    expand(resolved, out, seen, depth + 1);
    out.text += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
  }
}

}  // namespace

std::string shaderFile(const std::string& path) {
  if (const char* dir = std::getenv("MIRAGE_SHADER_DIR")) {
    std::ifstream in(std::filesystem::path(dir) / path, std::ios::binary);
    if (in) return std::string(std::istreambuf_iterator<char>(in), {});
  }
  for (const auto& f : embedded::files())
    if (path == f.path) return f.content;
  throwRuntime("shader file '{}' is not embedded in the binary", path);
}

ShaderSource loadShaderSource(const std::string& path, const std::vector<std::string>& defines) {
  ShaderSource source;
  source.text = "#version 450 core\n#define MIRAGE_GLSL 1\n";
  for (const std::string& d : defines) source.text += "#define " + d + "\n";
  std::set<std::string> seen;
  expand(path, source, seen, 0);
  return source;
}

std::string annotateShaderLog(const std::string& log, const std::vector<std::string>& files) {
  // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ...".
  static const std::regex location(R"(^(\d+)(?::(\d+)\(\d+\)|\((\d+)\)))");
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, location)) {
      size_t file = std::stoul(m[1].str());
      std::string number = m[2].matched ? m[2].str() : m[3].str();
      if (file < files.size()) line = files[file] + ":" + number + m.suffix().str();
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace mirage::gpu
