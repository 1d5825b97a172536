// Regular tests for what the fuzz targets found (fuzz/README.md lists each finding; the input
// that found it is kept in fuzz/corpus/<target>/finding-*).
#include "glide_window.h"

#include <glide.h>
#include <glide_shim.h>
#include <glideutl.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>

namespace {

using FuzzFindings = GlideWindowTest;

// glide_api_fuzz: a positive density so small that the farthest entry's fog rounds to zero made
// the normalisation divide by zero, and every entry NaN converted to a byte (undefined). Such a
// density is refused like a zero one, and the table is left alone.
TEST_F(FuzzFindings, FogTableOfAVanishingDensityIsRefused) {
  for (const float density : {std::numeric_limits<float>::denorm_min(), 1e-30f}) {
    GrFog_t table[GR_FOG_TABLE_SIZE];
    std::memset(table, 0x5A, sizeof table);
    GrFog_t untouched[GR_FOG_TABLE_SIZE];
    std::memcpy(untouched, table, sizeof table);
    glideShimClearError();
    guFogGenerateExp(table, density);
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE) << density;
    EXPECT_EQ(std::memcmp(table, untouched, sizeof table), 0);
    glideShimClearError();
    guFogGenerateExp2(table, density);
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE) << density;
    EXPECT_EQ(std::memcmp(table, untouched, sizeof table), 0);
  }
  // A small but usable density still gives a table that reaches full fog.
  GrFog_t table[GR_FOG_TABLE_SIZE];
  glideShimClearError();
  guFogGenerateExp(table, 1e-4f);
  expect_no_error();
  EXPECT_GE(table[GR_FOG_TABLE_SIZE - 1], 254);
}

// glide_api_fuzz: grLfbReadRegion of the depth buffer with an odd dst_stride stored 16-bit words
// at odd addresses (undefined). The words are now copied byte-wise: the same values as with an
// even stride, at row * stride.
TEST_F(FuzzFindings, DepthRegionReadWithAnOddStride) {
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0x1234);
  constexpr int kW = 4, kH = 3;
  std::uint16_t even[kW * kH] = {};
  ASSERT_EQ(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 2, 2, kW, kH, kW * 2, even), FXTRUE);
  constexpr int kOddStride = kW * 2 + 1;
  unsigned char odd[kOddStride * kH + 1] = {};
  ASSERT_EQ(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 2, 2, kW, kH, kOddStride, odd), FXTRUE);
  expect_no_error();
  for (int row = 0; row < kH; ++row) {
    for (int col = 0; col < kW; ++col) {
      std::uint16_t word;
      std::memcpy(&word, odd + row * kOddStride + col * 2, sizeof word);
      EXPECT_EQ(word, even[row * kW + col]) << row << "," << col;
    }
  }
}

// glide_api_fuzz: closing the window between glideShimBeginGL and glideShimEndGL left plain GL
// begun with no renderer, and glideShimEndGL then called through a null pointer. Closing the
// window ends plain GL: glideShimEndGL reports that none is begun, and a new window works.
TEST_F(FuzzFindings, ClosingTheWindowEndsPlainGl) {
  ASSERT_EQ(glideShimBeginGL(), FXTRUE);
  grSstWinClose();
  glideShimClearError();
  glideShimEndGL();
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT);
  glideShimClearError();
  ASSERT_EQ(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                         GR_ORIGIN_UPPER_LEFT, 2, 1),
            FXTRUE);
  grBufferClear(0, 0, 0);
  expect_no_error();
}

// glide_api_fuzz: guTexAllocateMemory of a chain whose odd/even mask selects none of its levels
// (one level, GR_LOD_256, which is even, with the odd mask). The shim was right and the fuzzer's
// rule wrong: like the driver (digutex.c), the allocation succeeds and takes the
// grTexTextureMemRequired of the mask's levels, 0 bytes, so the next chain starts where it would
// have. The rule now asks for exactly that size.
TEST_F(FuzzFindings, AllocatingAChainWithNoLevelOfItsMaskTakesNoMemory) {
  GrTexInfo info{};
  info.smallLod = GR_LOD_256;
  info.largeLod = GR_LOD_256;
  info.aspectRatio = GR_ASPECT_1x1;
  info.format = GR_TEXFMT_RGB_565;
  EXPECT_EQ(grTexTextureMemRequired(GR_MIPMAPLEVELMASK_ODD, &info), 0u);
  // guTexAllocateMemory of info's one-level chain with the odd/even mask `mask`.
  const auto allocate = [](FxU8 mask) {
    return guTexAllocateMemory(GR_TMU0, mask, 256, 256, GR_TEXFMT_RGB_565, GR_MIPMAP_DISABLE,
                               GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXTURECLAMP_WRAP,
                               GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_BILINEAR,
                               GR_TEXTUREFILTER_BILINEAR, 0.0f, FXFALSE);
  };
  const FxU32 free_before = guTexMemQueryAvail(GR_TMU0);
  glideShimClearError();
  const GrMipMapId_t empty = allocate(GR_MIPMAPLEVELMASK_ODD);
  expect_no_error();
  ASSERT_NE(empty, GR_NULL_MIPMAP_HANDLE);
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), free_before);
  // The same chain with both masks takes its whole 128 KB.
  const GrMipMapId_t whole = allocate(GR_MIPMAPLEVELMASK_BOTH);
  expect_no_error();
  ASSERT_NE(whole, GR_NULL_MIPMAP_HANDLE);
  EXPECT_EQ(free_before - guTexMemQueryAvail(GR_TMU0), 256u * 256u * 2u);
  EXPECT_EQ(guTexGetMipMapInfo(whole)->tmu_base_address,
            guTexGetMipMapInfo(empty)->tmu_base_address);
}

}  // namespace
