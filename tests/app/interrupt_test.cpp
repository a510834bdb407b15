// Ctrl-C and SIGTERM stop long work cleanly: the process exits with 128 + the signal soon after,
// says so, and leaves no half-written or temporary file behind.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include "core/atomic_file.h"
#include "core/interrupt.h"
#include "support/gl_test.h"
#include "support/test_files.h"

extern char** environ;

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

TEST(Interrupt, TheFlagThrowsWithTheSignalsExitCode) {
  clearInterrupt();
  EXPECT_NO_THROW(checkInterrupt());
  requestInterrupt(SIGTERM);
  EXPECT_TRUE(interruptRequested());
  try {
    checkInterrupt();
    ADD_FAILURE() << "no throw";
  } catch (const Interrupted& e) {
    EXPECT_EQ(int(e.code()), 143);
    EXPECT_NE(std::string(e.what()).find("SIGTERM"), std::string::npos) << e.what();
  }
  clearInterrupt();
  EXPECT_FALSE(interruptRequested());
}

TEST(Interrupt, AnUncommittedFileLeavesNothing) {
  const fs::path dir = testTempDir("interrupt-atomic");
  {
    AtomicFile file((dir / "out.png").string());
    std::ofstream(file.tempPath()) << "half";
    EXPECT_TRUE(fs::exists(file.tempPath()));
  }  // unwound, as an Interrupted would unwind it
  EXPECT_TRUE(fs::is_empty(dir));
}

struct Stopped {
  int code = -1;
  double seconds_after_signal = 0.0;
  std::string output;
};

// Starts `mirage args`, sends `signal` after `delay`, waits for it.
Stopped runAndSignal(const std::vector<std::string>& args, int signal,
                     std::chrono::milliseconds delay, const fs::path& log) {
  std::vector<std::string> argv_strings{MIRAGE_BINARY};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 2, 1);
  pid_t pid = 0;
  Stopped s;
  const int rc = posix_spawn(&pid, MIRAGE_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return s;
  std::this_thread::sleep_for(delay);
  kill(pid, signal);
  const auto sent = std::chrono::steady_clock::now();
  int status = 0;
  waitpid(pid, &status, 0);
  s.seconds_after_signal =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  s.code = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  std::ifstream in(log);
  s.output.assign(std::istreambuf_iterator<char>(in), {});
  return s;
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    names.push_back(fs::relative(e.path(), dir).string());
  return names;
}

// A ray-traced frame of minutes, stopped two seconds in.
TEST(Interrupt, CtrlCStopsALongRenderAndWritesNothing) {
  const fs::path dir = testTempDir("interrupt-render");
  fs::create_directories(dir / "out");
  const Stopped s =
      runAndSignal({"render", "--scene", "sphere-over-checker", "--method", "raytrace", "--spp",
                    "1024", "--size", "1024x1024", "-o", (dir / "out/frame.png").string()},
                   SIGINT, std::chrono::milliseconds(2000), dir / "log.txt");
  EXPECT_EQ(s.code, 130) << s.output;
  EXPECT_NE(s.output.find("interrupted by SIGINT"), std::string::npos) << s.output;
  EXPECT_LT(s.seconds_after_signal, 20.0);
  EXPECT_EQ(filesIn(dir / "out"), std::vector<std::string>{}) << s.output;
}

// compare under SIGTERM while its reference is traced: the report folder holds no partial file.
TEST(Interrupt, SigtermStopsCompareAndLeavesOnlyWholeFiles) {
  const fs::path dir = testTempDir("interrupt-compare");
  const Stopped s =
      runAndSignal({"compare", "--scene", "mirror-room", "--methods", "envmap", "--spp", "1024",
                    "--size", "720x512", "-o", (dir / "report").string()},
                   SIGTERM, std::chrono::milliseconds(2500), dir / "log.txt");
  EXPECT_EQ(s.code, 143) << s.output;
  EXPECT_NE(s.output.find("interrupted by SIGTERM"), std::string::npos) << s.output;
  EXPECT_LT(s.seconds_after_signal, 20.0);
  if (fs::exists(dir / "report"))
    for (const std::string& name : filesIn(dir / "report")) {
      EXPECT_EQ(name.find(".tmp."), std::string::npos) << name;
      EXPECT_NE(name, "metrics.json");
    }
}

// advise under SIGINT while it measures: its folder holds nothing (it writes only at the end).
TEST(Interrupt, CtrlCStopsAdviseAndWritesNothing) {
  const fs::path dir = testTempDir("interrupt-advise");
  fs::create_directories(dir / "out");
  const Stopped s = runAndSignal({"advise", "--scene", "gallery", "--size", "720x512", "--ssaa",
                                  "2", "-o", (dir / "out").string()},
                                 SIGINT, std::chrono::milliseconds(2500), dir / "log.txt");
  EXPECT_EQ(s.code, 130) << s.output;
  EXPECT_LT(s.seconds_after_signal, 20.0);
  EXPECT_EQ(filesIn(dir / "out"), std::vector<std::string>{}) << s.output;
}

// The viewer takes Ctrl-C as a close request: what it recorded and its report are written.
TEST(ViewUnderXvfb, CtrlCClosesTheWindowAndKeepsTheRecordings) {
  MIRAGE_NEED_DISPLAY();
  const fs::path dir = testTempDir("interrupt-view");
  const Stopped s = runAndSignal(
      {"view", "--scene", "sphere-over-checker", "--method", "envmap", "--size", "160x120",
       "--frames", "0", "--record-path", (dir / "path.camera.json").string(), "--report",
       (dir / "report.json").string()},
      SIGINT, std::chrono::milliseconds(3000), dir / "log.txt");
  EXPECT_EQ(s.code, 130) << s.output;
  EXPECT_NE(s.output.find("interrupted by SIGINT"), std::string::npos) << s.output;
  EXPECT_LT(s.seconds_after_signal, 20.0);
  EXPECT_TRUE(fs::is_regular_file(dir / "path.camera.json")) << s.output;
  EXPECT_TRUE(fs::is_regular_file(dir / "report.json")) << s.output;
  for (const std::string& name : filesIn(dir)) EXPECT_EQ(name.find(".tmp."), std::string::npos);
}

}  // namespace
}  // namespace mirage::test
