// GPU storage accounting (gpu/memory.h): textures and buffers charge the bytes their storage
// takes, computed here by hand, and give them back when they go; views share storage and add
// nothing; a buffer that grows is charged its new size.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/memory.h"
#include "gpu/texture.h"
#include "support/gl_test.h"

namespace mirage::test {
namespace {

class GpuMemory : public GlTest {};

TEST_F(GpuMemory, TexturesChargeTheirLevelsAndLayers) {
  const int64_t start = gpu::allocatedBytes();
  {
    // 64x32, 3 levels, 8 bytes a texel: (64*32 + 32*16 + 16*8) * 8.
    gpu::Texture flat = gpu::Texture::create2D(GL_RGBA16F, 64, 32, 3);
    EXPECT_EQ(gpu::allocatedBytes() - start, (2048 + 512 + 128) * 8);
    EXPECT_EQ(flat.storageBytes(), uint64_t((2048 + 512 + 128) * 8));
    // Two cubes of 8-texel faces, full mips (8, 4, 2, 1), 16 bytes a texel, 12 faces.
    gpu::Texture cubes = gpu::Texture::createCubeArray(GL_RGBA32F, 8, 2, 4);
    EXPECT_EQ(cubes.storageBytes(), uint64_t((64 + 16 + 4 + 1) * 12 * 16));
    const int64_t both = gpu::allocatedBytes();
    gpu::Texture view = gpu::Texture::view(cubes, GL_TEXTURE_2D, 3, 1);
    EXPECT_EQ(gpu::allocatedBytes(), both);
    gpu::Texture moved = std::move(flat);
    EXPECT_EQ(gpu::allocatedBytes(), both);
    gpu::Texture depth = gpu::Texture::create2D(GL_DEPTH_COMPONENT32F, 10, 10);
    EXPECT_EQ(gpu::allocatedBytes() - both, 400);
  }
  EXPECT_EQ(gpu::allocatedBytes(), start);
}

TEST_F(GpuMemory, BuffersChargeTheirSizeAndGrow) {
  const int64_t start = gpu::allocatedBytes();
  {
    gpu::Buffer buffer(1000);
    EXPECT_EQ(gpu::allocatedBytes() - start, 1000);
    std::vector<char> more(3000, 1);
    buffer.upload(more.data(), more.size());
    EXPECT_EQ(gpu::allocatedBytes() - start, 3000);
    buffer.upload(more.data(), 10);  // fits: no new storage
    EXPECT_EQ(gpu::allocatedBytes() - start, 3000);
  }
  EXPECT_EQ(gpu::allocatedBytes(), start);
}

}  // namespace
}  // namespace mirage::test
