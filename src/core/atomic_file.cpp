#include "core/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

#include <fmt/format.h>

#include "core/error.h"
#include "core/interrupt.h"

namespace mirage {

namespace {
std::string uniqueSuffix() {
  static std::random_device device;
  return std::to_string(::getpid()) + "." + std::to_string(device() & 0xffffff);
}
}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  std::filesystem::path p(path_);
  // Keep the extension last: some writers pick the format from it.
  std::string name =
      fmt::format(".{}.tmp.{}{}", p.stem().string(), uniqueSuffix(), p.extension().string());
  temp_path_ = (p.parent_path() / name).string();
  registerTemporaryFile(temp_path_.c_str());
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_path_.c_str());
  unregisterTemporaryFile(temp_path_.c_str());
}

void AtomicFile::commit() {
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    int err = errno;
    std::remove(temp_path_.c_str());
    throwRuntime("cannot write '{}': {}", path_, std::strerror(err));
  }
  committed_ = true;
}

void writeFileAtomic(const std::string& path, std::string_view content) {
  AtomicFile file(path);
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    if (!out) throwRuntime("cannot write '{}': {}", path, std::strerror(errno));
    out.write(content.data(), std::streamsize(content.size()));
    out.flush();
    if (!out) throwRuntime("cannot write '{}': {}", path, std::strerror(errno));
  }
  file.commit();
}

std::string readFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throwInput("'{}' is a directory, not a file", path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throwInput("cannot read '{}': {}", path, std::strerror(errno));
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throwInput("cannot read '{}': I/O error", path);
  return content;
}

}  // namespace mirage
