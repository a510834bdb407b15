#include "app/video.h"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/interrupt.h"

namespace mirage::app {

namespace fs = std::filesystem;

namespace {

int frameDigits(int count) {
  int digits = 4;
  for (int n = count - 1; n >= 10000; n /= 10) ++digits;
  return digits;
}

std::string withSuffix(const std::string& output, const std::string& suffix) {
  const fs::path p(output);
  return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

}  // namespace

std::string frameFileName(const std::string& output, int index, int count) {
  return withSuffix(output, fmt::format("_{:0{}d}", index, frameDigits(count)));
}

std::string framePattern(const std::string& output, int count) {
  return withSuffix(output, fmt::format("_%0{}d", frameDigits(count)));
}

std::string findFfmpeg() {
  if (const char* given = std::getenv("MIRAGE_FFMPEG")) return given;
  const char* path = std::getenv("PATH");
  if (!path) return "";
  std::string dirs = path;
  size_t start = 0;
  while (start <= dirs.size()) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / "ffmpeg";
    std::error_code ec;
    if (!candidate.parent_path().empty() && fs::is_regular_file(candidate, ec) &&
        access(candidate.c_str(), X_OK) == 0)
      return candidate.string();
    start = end + 1;
  }
  return "";
}

namespace {

// Single quotes for /bin/sh, so that any file name passes through unchanged.
std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

void encodeMp4(const std::string& ffmpeg, const std::string& pattern, double fps,
               const std::string& output) {
  AtomicFile file(output);
  // The temporary name keeps the .mp4 extension, from which ffmpeg picks the container.
  const std::string& temp = file.tempPath();
  const std::string log = file.tempPath() + ".log";
  const std::string command = fmt::format(
      "{} -hide_banner -loglevel error -y -framerate {} -i {} -c:v libx264 -pix_fmt yuv420p "
      "-vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' {} > {} 2>&1",
      shellQuote(ffmpeg), fps, shellQuote(pattern), shellQuote(temp), shellQuote(log));
  const int status = std::system(command.c_str());
  // Ctrl-C reaches ffmpeg (and its shell) too; std::system ignores it in mirage meanwhile.
  checkInterrupt();
  if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGTERM))
    throw Interrupted(WTERMSIG(status));
  if (WIFEXITED(status) &&
      (WEXITSTATUS(status) == 128 + SIGINT || WEXITSTATUS(status) == 128 + SIGTERM))
    throw Interrupted(WEXITSTATUS(status) - 128);
  std::string message;
  try {
    message = readFile(log);
  } catch (const InputError&) {
  }
  std::error_code ec;
  fs::remove(log, ec);
  if (status != 0 || !fs::is_regular_file(temp, ec)) {
    fs::remove(temp, ec);
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r'))
      message.pop_back();
    if (message.size() > 400) message = message.substr(message.size() - 400);
    throwRuntime("{}: ffmpeg ({}) failed with status {}{}", output, ffmpeg,
                 WIFEXITED(status) ? WEXITSTATUS(status) : status,
                 message.empty() ? "" : ": " + message);
  }
  file.commit();
}

}  // namespace mirage::app
