// Texture::generateMipmaps(first_layer, layers): the mip chain of some layers of an array only,
// each level the 2:1 box average of the one above (what a linear blit of an even size gives,
// checked against averages computed here), the other layers' levels left as they were.
#include <gtest/gtest.h>

#include <vector>

#include "gpu/texture.h"
#include "support/gl_test.h"

namespace mirage::test {
namespace {

class TextureMipmap : public GlTest {};

constexpr int kSize = 16, kLevels = 5, kLayers = 3;

std::vector<float> level0(int layer) {
  std::vector<float> texels(size_t(kSize * kSize * 4));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 4; ++c)
        texels[size_t(((y * kSize) + x) * 4 + c)] = float((x * 7 + y * 3 + c + layer) % 11) / 10.0f;
  return texels;
}

// The box average of `above` (side 2n) into side n.
std::vector<float> halve(const std::vector<float>& above, int side) {
  const int n = side / 2;
  std::vector<float> out(size_t(n * n * 4));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      for (int c = 0; c < 4; ++c) {
        float sum = 0.0f;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx)
            sum += above[size_t((((2 * y + dy) * side) + 2 * x + dx) * 4 + c)];
        out[size_t((y * n + x) * 4 + c)] = sum / 4.0f;
      }
  return out;
}

std::vector<float> read(const gpu::Texture& t, int level, int layer) {
  const int side = kSize >> level;
  std::vector<float> out(size_t(side * side * 4));
  t.downloadLayer(level, layer, GL_RGBA, GL_FLOAT, out.data(), out.size() * sizeof(float));
  return out;
}

TEST_F(TextureMipmap, OneLayersChainIsItsBoxAverageAndTheOthersAreKept) {
  gpu::Texture t = gpu::Texture::create2DArray(GL_RGBA32F, kSize, kSize, kLayers, kLevels);
  const std::vector<float> marker(size_t(kSize * kSize * 4), 0.25f);
  for (int layer = 0; layer < kLayers; ++layer) {
    t.uploadLayer(0, layer, GL_RGBA, GL_FLOAT, level0(layer).data());
    for (int level = 1; level < kLevels; ++level)
      t.uploadLayer(level, layer, GL_RGBA, GL_FLOAT, marker.data());
  }
  t.generateMipmaps(1, 1);
  std::vector<float> expected = level0(1);
  for (int level = 1; level < kLevels; ++level) {
    expected = halve(expected, kSize >> (level - 1));
    const std::vector<float> got = read(t, level, 1);
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i)
      ASSERT_NEAR(got[i], expected[i], 1e-5f) << "level " << level << " value " << i;
    for (int other : {0, 2})
      for (float v : read(t, level, other)) ASSERT_EQ(v, 0.25f) << "layer " << other;
  }
}

TEST_F(TextureMipmap, LayersOutsideTheArrayAreRefused) {
  gpu::Texture t = gpu::Texture::create2DArray(GL_RGBA16F, kSize, kSize, kLayers, kLevels);
  EXPECT_THROW(t.generateMipmaps(2, 2), std::exception);
}

}  // namespace
}  // namespace mirage::test
