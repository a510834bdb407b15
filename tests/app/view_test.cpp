// `mirage view`: without a display it says so and exits 2; under Xvfb (ctest's
// "ViewUnderXvfb") it opens, renders N frames and its screenshot matches `mirage render` of the
// same camera; bad input exits 2.
#include <gtest/gtest.h>

#include "core/image.h"
#include "eval/metrics.h"
#include "support/gl_test.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

TEST(ViewCli, WithoutDisplayExitsTwoAndSaysSo) {
  const auto dir = testTempDir("view-nodisplay");
  const CliResult r =
      runMirage("view --scene mirror-room --frames 1 --screenshot " + (dir / "v.png").string(),
                "env -u DISPLAY");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("xvfb-run"), std::string::npos) << r.output;
}

TEST(ViewCli, BadInputExitsTwo) {
  const auto dir = testTempDir("view-bad");
  for (const std::string& bad :
       {std::string("view --scene mirror-room --method nosuch --frames 1"),
        std::string("view --scene mirror-room --frames -1"),
        "view --scene mirror-room --screenshot " + (dir / "v.png").string()}) {
    const CliResult r = runMirage(bad);
    EXPECT_EQ(r.code, 2) << bad << "\n" << r.output;
  }
}

// The viewer's frame is the headless renderer's: the same FrameRenderer, the same camera.
TEST(ViewUnderXvfb, ScreenshotMatchesTheHeadlessRender) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-shot");
  for (const char* method : {"envmap", "planar", "zexel"}) {
    const std::string common =
        std::string(" --scene mirror-room --size 320x240 --order 1 --method ") + method;
    const CliResult v =
        runMirage("view" + common + " --frames 4 --screenshot " + (dir / "view.png").string());
    ASSERT_EQ(v.code, 0) << v.output;
    const CliResult r = runMirage("render" + common + " -o " + (dir / "render.png").string());
    ASSERT_EQ(r.code, 0) << r.output;
    const Image a = readImage((dir / "view.png").string());
    const Image b = readImage((dir / "render.png").string());
    ASSERT_EQ(a.width(), 320);
    ASSERT_EQ(a.height(), 240);
    const double psnr = psnrFromMse(meanSquaredError(a, b));
    std::printf("%s: viewer screenshot vs headless render %.1f dB\n", method, psnr);
    EXPECT_GT(psnr, 45.0) << method;
  }
}

}  // namespace
}  // namespace mirage::test
