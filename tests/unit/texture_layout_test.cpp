// Texture memory queries: grTexCalcMemRequired / grTexTextureMemRequired against sizes worked
// out by hand, and the TMU address range (grTexMinAddress / grTexMaxAddress).
//
// How 3dfx's SST-1 Glide 2.x computes the size (glide2x/sst1/glide/src/ditex.c,
// _grTexTextureMemRequired): sum the TMU footprint of the selected levels in texels
// (_grMipMapSize[aspect][lod], aspect folded so 1x8 = 8x1), double it for 16-bit formats
// (format >= GR_TEXFMT_16BIT), then round up to 8 bytes. EVEN selects the even LOD numbers
// (GR_LOD_256 = 0, 64, 16, 4, 1), ODD the others. The footprint is the level's texel count, except
// that the TMU gives every level at least 4 texels and pads narrow ones:
//   1:1  65536 16384 4096 1024 256 64 16  4 4     (256x256 .. 2x2, 1x1)
//   2:1  32768  8192 2048  512 128 32  8  4 4     (256x128 .. 4x2, 2x1, 1x1)
//   8:1   8192  2048  512  128  32 16  8  4 4     (256x32 .. 16x2, 8x1 = 16, 4x1 = 8, 2x1, 1x1)
// Where the rounding to 8 bytes hides the difference, plain texel counts give the same answer;
// the first tests use only such cases, the last one the narrow levels where it does not.
#include "context.h"
#include "glide_window.h"

#include <vector>

namespace {

using glide_shim::current;

constexpr FxU32 kTmuMemoryBytes = 2u * 1024u * 1024u;

FxU32 calc(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect, GrTextureFormat_t format) {
  return grTexCalcMemRequired(small_lod, large_lod, aspect, format);
}

FxU32 texture(FxU32 even_odd, GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
              GrTextureFormat_t format) {
  GrTexInfo info{small_lod, large_lod, aspect, format, nullptr};
  return grTexTextureMemRequired(even_odd, &info);
}

using TextureLayoutTest = GlideWindowTest;

TEST_F(TextureLayoutTest, SingleLargeLevels) {
  // 256x256 RGB_565: 65536 texels * 2 bytes = 131072.
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 131072u);
  // Every 16-bit format is 2 bytes per texel: ARGB_8332 (8), 1555, 4444, AI_88.
  for (GrTextureFormat_t format : {GR_TEXFMT_ARGB_8332, GR_TEXFMT_ARGB_1555, GR_TEXFMT_ARGB_4444,
                                   GR_TEXFMT_ALPHA_INTENSITY_88}) {
    EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, format), 131072u) << "format " << format;
  }
  // 8-bit formats (RGB_332, ALPHA_8, INTENSITY_8, AI_44) half that: 65536.
  for (GrTextureFormat_t format : {GR_TEXFMT_RGB_332, GR_TEXFMT_ALPHA_8, GR_TEXFMT_INTENSITY_8,
                                   GR_TEXFMT_ALPHA_INTENSITY_44}) {
    EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, format), 65536u) << "format " << format;
  }
  // 64x64 565: 4096 * 2 = 8192.
  EXPECT_EQ(calc(GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 8192u);
  // Aspect 2x1 at LOD 256: 256x128 = 32768 texels -> 65536 bytes in 565, 32768 in 8 bits;
  // 1x2 (128x256) the same.
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_2x1, GR_TEXFMT_RGB_565), 65536u);
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x2, GR_TEXFMT_RGB_565), 65536u);
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_2x1, GR_TEXFMT_ALPHA_8), 32768u);
  // Aspect 4x1 at LOD 256: 256x64 = 16384 texels -> 32768 bytes in 565.
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_4x1, GR_TEXFMT_RGB_565), 32768u);
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x4, GR_TEXFMT_RGB_565), 32768u);
  // Aspect 1x8 at LOD 256: 32x256 = 8192 texels -> 16384 bytes in 565, 8192 in 8 bits; 8x1 too.
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x8, GR_TEXFMT_RGB_565), 16384u);
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_8x1, GR_TEXFMT_RGB_565), 16384u);
  EXPECT_EQ(calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x8, GR_TEXFMT_INTENSITY_8), 8192u);
  // Aspect 1x8 at LOD 64: 8x64 = 512 texels -> 1024 bytes.
  EXPECT_EQ(calc(GR_LOD_64, GR_LOD_64, GR_ASPECT_1x8, GR_TEXFMT_RGB_565), 1024u);
  expect_no_error();
}

TEST_F(TextureLayoutTest, SmallLevelsRoundUpToEightBytes) {
  // 1x1: 1 texel (footprint 4) -> 2 (8) bytes in 565, rounded up to 8; 8-bit also 8.
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 8u);
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_ALPHA_8), 8u);
  // 2x2: 4 texels -> 8 bytes in 565; 4 bytes in 8 bits, rounded up to 8.
  EXPECT_EQ(calc(GR_LOD_2, GR_LOD_2, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 8u);
  EXPECT_EQ(calc(GR_LOD_2, GR_LOD_2, GR_ASPECT_1x1, GR_TEXFMT_ALPHA_8), 8u);
  // 4x4: 16 texels -> 32 bytes in 565, 16 in 8 bits.
  EXPECT_EQ(calc(GR_LOD_4, GR_LOD_4, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 32u);
  EXPECT_EQ(calc(GR_LOD_4, GR_LOD_4, GR_ASPECT_1x1, GR_TEXFMT_ALPHA_8), 16u);
  // Chain 4x4 .. 1x1 in 565: (16 + 4 + 1) * 2 = 42 -> 48 (the TMU footprint 16+4+4 = 24 texels
  // gives 48 exactly). In 8 bits: 21 -> 24.
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_4, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 48u);
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_4, GR_ASPECT_1x1, GR_TEXFMT_ALPHA_8), 24u);
  // 2x1 aspect, LOD 2 (2x1): 2 texels (footprint 4) -> 8 bytes in 565 either way.
  EXPECT_EQ(calc(GR_LOD_2, GR_LOD_2, GR_ASPECT_2x1, GR_TEXFMT_RGB_565), 8u);
  expect_no_error();
}

TEST_F(TextureLayoutTest, FullMipMapChains) {
  // 256..1 in 565: 2 * (65536+16384+4096+1024+256+64+16+4+1) = 2 * 87381 = 174762, rounded up
  // to 8 = 174768 (the TMU footprint ...+4+4 = 87384 texels gives 174768 directly).
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 174768u);
  // 8-bit: 87381 -> 87384.
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_332), 87384u);
  // 256..64 in 565: 2 * (65536+16384+4096) = 172032 (a multiple of 8).
  EXPECT_EQ(calc(GR_LOD_64, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 172032u);
  // 64..8 in 4444: 2 * (4096+1024+256+64) = 10880.
  EXPECT_EQ(calc(GR_LOD_8, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_ARGB_4444), 10880u);
  // 2x1 chain 256x128 .. 1x1 in 8 bits: 32768+8192+2048+512+128+32+8+2+1 = 43691 -> 43696
  // (footprint ...+8+4+4 = 43696 exactly).
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_256, GR_ASPECT_2x1, GR_TEXFMT_ALPHA_8), 43696u);
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x2, GR_TEXFMT_ALPHA_8), 43696u);
  // 2x1 chain 256x128 .. 32x16 in 565: 2 * (32768+8192+2048+512) = 87040.
  EXPECT_EQ(calc(GR_LOD_32, GR_LOD_256, GR_ASPECT_2x1, GR_TEXFMT_RGB_565), 87040u);
  // 1x8 chain 32x256 .. 2x16 in 565: 2 * (8192+2048+512+128+32) = 21824.
  EXPECT_EQ(calc(GR_LOD_16, GR_LOD_256, GR_ASPECT_1x8, GR_TEXFMT_RGB_565), 21824u);
  EXPECT_EQ(calc(GR_LOD_16, GR_LOD_256, GR_ASPECT_8x1, GR_TEXFMT_RGB_565), 21824u);
  expect_no_error();
}

TEST_F(TextureLayoutTest, TextureMemRequiredAgreesWithCalcForBothLevels) {
  for (GrAspectRatio_t aspect = GR_ASPECT_8x1; aspect <= GR_ASPECT_1x8; ++aspect) {
    for (GrTextureFormat_t format : {GR_TEXFMT_RGB_332, GR_TEXFMT_RGB_565}) {
      for (GrLOD_t large = GR_LOD_256; large <= GR_LOD_1; ++large) {
        for (GrLOD_t small = large; small <= GR_LOD_1; ++small) {
          EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_BOTH, small, large, aspect, format),
                    calc(small, large, aspect, format))
              << "aspect " << aspect << " format " << format << " lods " << large << ".." << small;
          const FxU32 size = calc(small, large, aspect, format);
          EXPECT_EQ(size % 8, 0u);
          EXPECT_GT(size, 0u);
        }
      }
    }
  }
  expect_no_error();
}

TEST_F(TextureLayoutTest, EvenAndOddMasksSelectAlternateLevels) {
  // 256..1 in 565. EVEN = LODs 256, 64, 16, 4, 1: 65536+4096+256+16+1 = 69905 texels
  // -> 139810 bytes -> 139816 (footprint ...+16+4 = 69908 -> 139816 directly).
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_EVEN, GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 139816u);
  // ODD = LODs 128, 32, 8, 2: 16384+1024+64+4 = 17476 texels -> 34952 bytes (a multiple of 8).
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_ODD, GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 34952u);
  // 256..64: EVEN = 256 and 64: 2 * (65536+4096) = 139264; ODD = 128: 2 * 16384 = 32768;
  // together the 172032 of BOTH.
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_EVEN, GR_LOD_64, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 139264u);
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_ODD, GR_LOD_64, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 32768u);
  // The chain starting at an odd level: 128..16 EVEN = 64, 16: 2 * (4096+256) = 8704;
  // ODD = 128, 32: 2 * (16384+1024) = 34816.
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_EVEN, GR_LOD_16, GR_LOD_128, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 8704u);
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_ODD, GR_LOD_16, GR_LOD_128, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 34816u);
  // 8-bit, 256..64: EVEN 65536+4096 = 69632, ODD 16384.
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_EVEN, GR_LOD_64, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_ALPHA_8), 69632u);
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_ODD, GR_LOD_64, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_ALPHA_8), 16384u);
  // A single odd level asked for its EVEN levels holds none: 0 bytes; its ODD ones, all of it.
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_EVEN, GR_LOD_128, GR_LOD_128, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 0u);
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_ODD, GR_LOD_128, GR_LOD_128, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), 32768u);
  // 2x1 chain 256x128 .. 1x1 in 565: EVEN = 32768+2048+128+8+1 = 34953 -> 69906 -> 69912
  // (footprint 32768+2048+128+8+4 = 34956 -> 69912); ODD = 8192+512+32+2 = 8738 -> 17476 -> 17480
  // (footprint ...+4 = 8740 -> 17480).
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_EVEN, GR_LOD_1, GR_LOD_256, GR_ASPECT_2x1, GR_TEXFMT_RGB_565), 69912u);
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_ODD, GR_LOD_1, GR_LOD_256, GR_ASPECT_2x1, GR_TEXFMT_RGB_565), 17480u);
  expect_no_error();
}

// The narrow small levels, where the SST-1 driver's TMU footprint (see the table at the top)
// differs from a plain texel count even after rounding to 8 bytes.
TEST_F(TextureLayoutTest, NarrowSmallLevelsUseTheSst1Footprint) {
  // 8x1 aspect, LOD 8 (an 8x1 level): footprint 16 texels -> 32 bytes in 565, 16 in 8 bits
  // (8 texels would give 16 and 8).
  EXPECT_EQ(calc(GR_LOD_8, GR_LOD_8, GR_ASPECT_8x1, GR_TEXFMT_RGB_565), 32u);
  EXPECT_EQ(calc(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x8, GR_TEXFMT_ALPHA_8), 16u);
  // 4x1 aspect, LOD 4 (a 4x1 level): footprint 8 texels -> 16 bytes in 565 (4 texels: 8).
  EXPECT_EQ(calc(GR_LOD_4, GR_LOD_4, GR_ASPECT_4x1, GR_TEXFMT_RGB_565), 16u);
  // 2x1 chain 256x128 .. 1x1 in 565: footprint 32768+8192+2048+512+128+32+8+4+4 = 43696 texels
  // -> 87392 bytes (43691 texels would give 87382 -> 87384).
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_256, GR_ASPECT_2x1, GR_TEXFMT_RGB_565), 87392u);
  // 1x8 chain 32x256 .. 1x1: footprint 8192+2048+512+128+32+16+8+4+4 = 10944 texels -> 21888
  // bytes in 565, 10944 in 8 bits (10927 texels would give 21856 and 10928).
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x8, GR_TEXFMT_RGB_565), 21888u);
  EXPECT_EQ(calc(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x8, GR_TEXFMT_ALPHA_8), 10944u);
  // Its EVEN levels (256, 64, 16, 4, 1): 8192+512+32+8+4 = 8748 -> 17496 bytes in 565;
  // ODD (128, 32, 8, 2): 2048+128+16+4 = 2196 -> 4392.
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_EVEN, GR_LOD_1, GR_LOD_256, GR_ASPECT_1x8, GR_TEXFMT_RGB_565), 17496u);
  EXPECT_EQ(texture(GR_MIPMAPLEVELMASK_ODD, GR_LOD_1, GR_LOD_256, GR_ASPECT_1x8, GR_TEXFMT_RGB_565), 4392u);
  expect_no_error();
}

TEST_F(TextureLayoutTest, AddressRangeIsTheTwoMegabyteTmu) {
  const FxU32 min = grTexMinAddress(GR_TMU0);
  const FxU32 max = grTexMaxAddress(GR_TMU0);
  expect_no_error();
  EXPECT_EQ(min, 0u);
  EXPECT_LT(max, kTmuMemoryBytes);
  EXPECT_EQ(max % 8, 0u) << "texture start addresses are 8-byte aligned";
  // As in the SST-1 driver (total_mem - 8): the smallest texture fits exactly at the top.
  EXPECT_EQ(max + calc(GR_LOD_1, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565), kTmuMemoryBytes);
  // The hardware query agrees on the size.
  GrHwConfiguration hw;
  ASSERT_TRUE(grSstQueryHardware(&hw));
  EXPECT_EQ(static_cast<FxU32>(hw.SSTs[0].sstBoard.VoodooConfig.tmuConfig[0].tmuRam) << 20, kTmuMemoryBytes);
  // Eight 256x256 565 textures (8 * 131072 = 1 MB) fit between min and max back to back.
  EXPECT_GE(max - min + 8u, 8u * calc(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565));
}

TEST_F(TextureLayoutTest, DownloadsAtTheEndsOfTheRangeLandInTmuMemory) {
  const FxU32 max = grTexMaxAddress(GR_TMU0);
  // A 2x2 565 texture (8 bytes) at the highest start address, one at the lowest.
  std::vector<FxU16> top = {0x1111, 0x2222, 0x3333, 0x4444};
  std::vector<FxU16> bottom = {0xAAAA, 0xBBBB, 0xCCCC, 0xDDDD};
  GrTexInfo top_info{GR_LOD_2, GR_LOD_2, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, top.data()};
  GrTexInfo bottom_info{GR_LOD_2, GR_LOD_2, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, bottom.data()};
  grTexDownloadMipMap(GR_TMU0, max, GR_MIPMAPLEVELMASK_BOTH, &top_info);
  grTexDownloadMipMap(GR_TMU0, grTexMinAddress(GR_TMU0), GR_MIPMAPLEVELMASK_BOTH, &bottom_info);
  grTexSource(GR_TMU0, max, GR_MIPMAPLEVELMASK_BOTH, &top_info);
  expect_no_error();
  const std::vector<std::uint8_t> &memory = current().tmu.memory;
  ASSERT_EQ(memory.size(), kTmuMemoryBytes);
  // Little-endian words, byte for byte.
  EXPECT_EQ(memory[max], 0x11);
  EXPECT_EQ(memory[max + 7], 0x44);
  EXPECT_EQ(memory[0], 0xAA);
  EXPECT_EQ(memory[7], 0xDD);
  EXPECT_TRUE(current().tmu.source.valid);
  EXPECT_EQ(current().tmu.source.address, max);
}

}  // namespace
