// The gu texture manager's bookkeeping: where guTexAllocateMemory places mip maps (from 0
// upwards, each taking grTexTextureMemRequired bytes), the chain base and register values it
// records, running out of memory and of ids, guTexMemReset and grSstWinOpen emptying it,
// guTexChangeAttributes, and the errors for bad ids and arguments. Expected numbers are worked
// out here from the SST-1 driver's tables (_grMipMapSize, in texels: 65536, 16384, 4096, 1024,
// 256, 64, 16, 4, 4 for square levels 256..1) and register layout (sst.h).
#include "glide_window.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace {

constexpr FxU32 kTmuBytes = 2u * 1024u * 1024u;
// A whole square 256..1 chain of 16-bit texels: (65536 + 16384 + ... + 4 + 4) x 2.
constexpr FxU32 kFull565Chain = 174768;
// A square 64..1 chain of 8-bit texels: 4096 + 1024 + 256 + 64 + 16 + 4 + 4.
constexpr FxU32 kSmallP8Chain = 5464;

class GuTextureManagerTest : public GlideWindowTest {
 protected:
  // A mip map with every mode at its plainest; the tests vary what they check.
  static GrMipMapId_t allocate(FxU8 mask, GrTextureFormat_t format, GrLOD_t small_lod,
                               GrLOD_t large_lod, GrAspectRatio_t aspect = GR_ASPECT_1x1,
                               GrMipMapMode_t mipmap = GR_MIPMAP_NEAREST) {
    return guTexAllocateMemory(GR_TMU0, mask, 0, 0, format, mipmap, small_lod, large_lod, aspect,
                               GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP,
                               GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_POINT_SAMPLED,
                               0.0f, FXFALSE);
  }
  static GrMipMapId_t allocate_full_565() {
    return allocate(GR_MIPMAPLEVELMASK_BOTH, GR_TEXFMT_RGB_565, GR_LOD_1, GR_LOD_256);
  }
  static GrMipMapId_t allocate_small_p8() {
    return allocate(GR_MIPMAPLEVELMASK_BOTH, GR_TEXFMT_P_8, GR_LOD_1, GR_LOD_64);
  }

  // Expects the last call to have been refused with `kind`, naming `function`.
  static void expect_refused(GlideShimError kind, const char *function) {
    EXPECT_EQ(glideShimGetLastError(), kind) << glideShimGetLastErrorMessage();
    EXPECT_NE(std::strstr(glideShimGetLastErrorMessage(), function), nullptr)
        << glideShimGetLastErrorMessage();
    glideShimClearError();
  }
};

TEST_F(GuTextureManagerTest, AllocationsStartAtZeroAndFollowEachOther) {
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), kTmuBytes);
  const GrMipMapId_t first = allocate_full_565();
  const GrMipMapId_t second = allocate_small_p8();
  expect_no_error();
  EXPECT_EQ(first, 0u);
  EXPECT_EQ(second, 1u);
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), kTmuBytes - kFull565Chain - kSmallP8Chain);
  // The record holds the chain base, where a 256 level would start: the first chain starts
  // with its 256 level at 0; the second starts at 174768 with its 64 level, whose offset in a
  // full 8-bit chain is 65536 + 16384.
  EXPECT_EQ(guTexGetMipMapInfo(first)->tmu_base_address, 0u);
  EXPECT_EQ(guTexGetMipMapInfo(second)->tmu_base_address, kFull565Chain - 81920u);
}

TEST_F(GuTextureManagerTest, EvenAndOddChainsTakeOnlyTheirLevels) {
  // Even levels of 128..1 (64, 16, 4, 1): 4096 + 256 + 16 + 4 texels of 2 bytes.
  const GrMipMapId_t even = allocate(GR_MIPMAPLEVELMASK_EVEN, GR_TEXFMT_RGB_565, GR_LOD_1,
                                     GR_LOD_128);
  // Odd levels of 128..1 (128, 32, 8, 2): 16384 + 1024 + 64 + 4 texels of 2 bytes.
  const GrMipMapId_t odd = allocate(GR_MIPMAPLEVELMASK_ODD, GR_TEXFMT_RGB_565, GR_LOD_1,
                                    GR_LOD_128, GR_ASPECT_1x1, GR_MIPMAP_DISABLE);
  expect_no_error();
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), kTmuBytes - 8744u - 34952u);
  const GrMipMapInfo *even_info = guTexGetMipMapInfo(even);
  const GrMipMapInfo *odd_info = guTexGetMipMapInfo(odd);
  // An even chain whose largest level is odd is based as if it began at the next even level
  // (_grTexCalcBaseAddress): 0 - 256 level's 131072 bytes, wrapped as the driver's FxU32.
  EXPECT_EQ(even_info->tmu_base_address, static_cast<FxU32>(-131072));
  EXPECT_EQ(odd_info->tmu_base_address, 8744u);  // no odd level comes before 128
  // tLOD: lodmin 128 (1 << 2), lodmax 1 (8 << 8) or, mip-mapping off, 128 (1 << 8); the split
  // bit (1 << 19) and for odd chains the odd bit (1 << 18).
  EXPECT_EQ(even_info->tLOD, 0x80804u);
  EXPECT_EQ(odd_info->tLOD, 0xC0104u);
  EXPECT_EQ(even_info->odd_even_mask, static_cast<FxU32>(GR_MIPMAPLEVELMASK_EVEN));
}

TEST_F(GuTextureManagerTest, RecordHoldsTheDriversRegisterValues) {
  const GrMipMapId_t id = guTexAllocateMemory(
      GR_TMU0, GR_MIPMAPLEVELMASK_BOTH, 64, 32, GR_TEXFMT_RGB_565, GR_MIPMAP_NEAREST, GR_LOD_1,
      GR_LOD_64, GR_ASPECT_2x1, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_WRAP,
      GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_POINT_SAMPLED, 0.5f, FXFALSE);
  expect_no_error();
  const GrMipMapInfo *info = guTexGetMipMapInfo(id);
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->valid, FXTRUE);
  EXPECT_EQ(info->width, 64);
  EXPECT_EQ(info->height, 32);
  EXPECT_EQ(info->format, GR_TEXFMT_RGB_565);
  EXPECT_EQ(info->lod_min, GR_LOD_1);
  EXPECT_EQ(info->lod_max, GR_LOD_64);
  EXPECT_EQ(info->aspect_ratio, GR_ASPECT_2x1);
  EXPECT_EQ(info->tmu, GR_TMU0);
  EXPECT_EQ(info->data, nullptr);
  EXPECT_EQ(info->lod_bias, 2u);  // quarters
  // textureMode: format 0xA << 8, clamp W (8), perspective (1), min bilinear (2), clamp S (0x40).
  EXPECT_EQ(info->tTextureMode, 0xA4Bu);
  // tLOD: lodmin 64 (2 << 2), lodmax 1 (8 << 8), bias 2 << 12, aspect 2:1 with s wider
  // (1 << 21 | 1 << 20).
  EXPECT_EQ(info->tLOD, 0x302808u);
  // 2:1 levels 64x32..1x1 take 2048 + 512 + 128 + 32 + 8 + 4 + 4 texels of 2 bytes.
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), kTmuBytes - 5472u);
}

TEST_F(GuTextureManagerTest, TrilinearBitsAndNegativeBias) {
  const GrMipMapId_t id = guTexAllocateMemory(
      GR_TMU0, GR_MIPMAPLEVELMASK_BOTH, 256, 256, GR_TEXFMT_INTENSITY_8,
      GR_MIPMAP_NEAREST_DITHER, GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXTURECLAMP_WRAP,
      GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR, -0.5f, FXTRUE);
  expect_no_error();
  const GrMipMapInfo *info = guTexGetMipMapInfo(id);
  // (-0.5 + 0.125) / 0.25 = -1.5, truncated to -1 quarter: 63 in the 6-bit field.
  EXPECT_EQ(info->lod_bias, 63u);
  EXPECT_EQ(info->trilinear, FXTRUE);
  // Format 3, clamp W, perspective, both filters bilinear, LOD dither (0x10), trilinear (1 << 30).
  EXPECT_EQ(info->tTextureMode, 0x4000031Fu);
  // lodmax 1 (8 << 8), bias 63 << 12, and the allocation's trilinear odd bit (1 << 18).
  EXPECT_EQ(info->tLOD, 0x7F800u);
  // The driver's rebuild after guTexChangeAttributes leaves the odd bit out.
  EXPECT_EQ(guTexChangeAttributes(id, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1), FXTRUE);
  EXPECT_EQ(info->tLOD, 0x3F800u);
  EXPECT_EQ(info->tTextureMode, 0x4000031Fu);
}

TEST_F(GuTextureManagerTest, ExhaustedMemoryGivesTheNullHandleAndChangesNothing) {
  // Eleven whole 256..1 565 chains fit in 2 MB (1922448 bytes); the twelfth does not.
  for (GrMipMapId_t expected = 0; expected < 11; ++expected) {
    EXPECT_EQ(allocate_full_565(), expected);
  }
  expect_no_error();
  const FxU32 left = guTexMemQueryAvail(GR_TMU0);
  EXPECT_EQ(left, kTmuBytes - 11u * kFull565Chain);
  EXPECT_EQ(allocate_full_565(), GR_NULL_MIPMAP_HANDLE);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexAllocateMemory");
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), left);
  // A smaller chain still fits, with the next id and at the same free address.
  EXPECT_EQ(allocate_small_p8(), 11u);
  EXPECT_EQ(guTexGetMipMapInfo(11)->tmu_base_address, 11u * kFull565Chain - 81920u);
  expect_no_error();
}

TEST_F(GuTextureManagerTest, IdsRunOutAfterMaxMipMapsPerSst) {
  // A 1x1 8-bit chain takes 4 texels, rounded up to 8 bytes: 1024 of them fit easily.
  for (FxU32 i = 0; i < MAX_MIPMAPS_PER_SST; ++i) {
    ASSERT_EQ(allocate(GR_MIPMAPLEVELMASK_BOTH, GR_TEXFMT_P_8, GR_LOD_1, GR_LOD_1), i);
  }
  expect_no_error();
  const FxU32 left = guTexMemQueryAvail(GR_TMU0);
  EXPECT_EQ(left, kTmuBytes - 8u * MAX_MIPMAPS_PER_SST);
  EXPECT_EQ(allocate(GR_MIPMAPLEVELMASK_BOTH, GR_TEXFMT_P_8, GR_LOD_1, GR_LOD_1),
            GR_NULL_MIPMAP_HANDLE);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexAllocateMemory");
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), left);
}

TEST_F(GuTextureManagerTest, ResetFreesEverythingAndEmptiesTheRecords) {
  const GrMipMapId_t id = allocate_full_565();
  GrMipMapInfo *info = guTexGetMipMapInfo(id);
  guTexSource(id);
  EXPECT_EQ(guTexGetCurrentMipMap(GR_TMU0), id);
  guTexMemReset();
  expect_no_error();
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), kTmuBytes);
  EXPECT_EQ(guTexGetCurrentMipMap(GR_TMU0), GR_NULL_MIPMAP_HANDLE);
  EXPECT_EQ(info->valid, FXFALSE);  // the same record, now empty
  EXPECT_EQ(allocate_small_p8(), 0u);
  EXPECT_EQ(guTexGetMipMapInfo(0), info);
  expect_no_error();
}

TEST_F(GuTextureManagerTest, ReopeningTheWindowResetsTheManager) {
  allocate_full_565();
  allocate_full_565();
  guTexSource(1);
  grSstWinClose();
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1));
  expect_no_error();
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), kTmuBytes);
  EXPECT_EQ(guTexGetCurrentMipMap(GR_TMU0), GR_NULL_MIPMAP_HANDLE);
  EXPECT_EQ(allocate_small_p8(), 0u);
}

TEST_F(GuTextureManagerTest, SavedStateKeepsTheCurrentMipMap) {
  // The SST-1 GrState holds guTexSource's id (current_mm): grGlideSetState brings it back.
  const GrMipMapId_t first = allocate_full_565();
  const GrMipMapId_t second = allocate_small_p8();
  guTexSource(first);
  GrState saved;
  grGlideGetState(&saved);
  guTexSource(second);
  EXPECT_EQ(guTexGetCurrentMipMap(GR_TMU0), second);
  grGlideSetState(&saved);
  expect_no_error();
  EXPECT_EQ(guTexGetCurrentMipMap(GR_TMU0), first);
}

TEST_F(GuTextureManagerTest, LevelDownloadsAdvanceTheSourcePointer) {
  const GrMipMapId_t id = allocate(GR_MIPMAPLEVELMASK_EVEN, GR_TEXFMT_ARGB_1555, GR_LOD_1,
                                   GR_LOD_64, GR_ASPECT_1x2);
  std::vector<FxU16> texels(32 * 64 + 16 * 32 + 8 * 16 + 4 * 8 + 2 * 4 + 1 * 2 + 1, 0x8001);
  const void *source = texels.data();
  // Every level moves the pointer by its plain texel count, whether or not the mask keeps it.
  for (GrLOD_t lod = GR_LOD_64; lod <= GR_LOD_1; ++lod) guTexDownloadMipMapLevel(id, lod, &source);
  expect_no_error();
  EXPECT_EQ(source, static_cast<const void *>(texels.data() + texels.size()));
}

TEST_F(GuTextureManagerTest, BadIdsAreRefused) {
  const GrMipMapId_t id = allocate_small_p8();
  const std::vector<FxU8> texels(kSmallP8Chain, 7);
  guTexSource(id);
  glideShimClearError();

  guTexSource(GR_NULL_MIPMAP_HANDLE);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexSource");
  guTexSource(id + 1);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexSource");
  EXPECT_EQ(guTexGetCurrentMipMap(GR_TMU0), id);

  guTexDownloadMipMap(id + 5, texels.data(), nullptr);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexDownloadMipMap");
  const void *source = texels.data();
  guTexDownloadMipMapLevel(GR_NULL_MIPMAP_HANDLE, GR_LOD_64, &source);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexDownloadMipMapLevel");
  EXPECT_EQ(guTexChangeAttributes(id + 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1), FXFALSE);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexChangeAttributes");

  // An id of the table not yet handed out gives its empty record, with an error; an id past
  // the table gives NULL.
  const GrMipMapInfo *unallocated = guTexGetMipMapInfo(id + 3);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexGetMipMapInfo");
  ASSERT_NE(unallocated, nullptr);
  EXPECT_EQ(unallocated->valid, FXFALSE);
  EXPECT_EQ(guTexGetMipMapInfo(MAX_MIPMAPS_PER_SST), nullptr);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexGetMipMapInfo");
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), kTmuBytes - kSmallP8Chain);
}

TEST_F(GuTextureManagerTest, BadArgumentsAreRefusedWithoutAllocating) {
  // One argument bad at a time; each call must return the null handle with the error's kind.
  auto refused = [](GlideShimError kind, GrChipID_t tmu, FxU8 mask, GrTextureFormat_t format,
                    GrMipMapMode_t mipmap, GrLOD_t small_lod, GrLOD_t large_lod,
                    GrAspectRatio_t aspect, GrTextureClampMode_t clamp,
                    GrTextureFilterMode_t filter, float bias) {
    glideShimClearError();
    EXPECT_EQ(guTexAllocateMemory(tmu, mask, 8, 8, format, mipmap, small_lod, large_lod, aspect,
                                  clamp, GR_TEXTURECLAMP_WRAP, filter,
                                  GR_TEXTUREFILTER_POINT_SAMPLED, bias, FXFALSE),
              GR_NULL_MIPMAP_HANDLE);
    expect_refused(kind, "guTexAllocateMemory");
  };
  const FxU8 both = GR_MIPMAPLEVELMASK_BOTH;
  const GrTextureFormat_t rgb = GR_TEXFMT_RGB_565;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // Arguments: kind, tmu, mask, format, mip-map mode, small LOD, large LOD, aspect, clamp,
  // filter, bias.
  refused(GLIDESHIM_ERR_OUT_OF_RANGE, GR_TMU1, both, rgb, 0, 8, 5, 3, 0, 0, 0.0f);
  refused(GLIDESHIM_ERR_INVALID_ENUM, GR_TMU0, 0, rgb, 0, 8, 5, 3, 0, 0, 0.0f);
  refused(GLIDESHIM_ERR_INVALID_ENUM, GR_TMU0, 4, rgb, 0, 8, 5, 3, 0, 0, 0.0f);
  refused(GLIDESHIM_ERR_INVALID_ENUM, GR_TMU0, both, GR_TEXFMT_RSVD0, 0, 8, 5, 3, 0, 0, 0.0f);
  refused(GLIDESHIM_ERR_INCONSISTENT, GR_TMU0, both, rgb, 0, 5, 8, 3, 0, 0, 0.0f);
  refused(GLIDESHIM_ERR_INVALID_ENUM, GR_TMU0, both, rgb, 0, 9, 5, 3, 0, 0, 0.0f);
  refused(GLIDESHIM_ERR_INVALID_ENUM, GR_TMU0, both, rgb, 0, 8, 5, 7, 0, 0, 0.0f);
  refused(GLIDESHIM_ERR_INVALID_ENUM, GR_TMU0, both, rgb, 3, 8, 5, 3, 0, 0, 0.0f);
  refused(GLIDESHIM_ERR_INVALID_ENUM, GR_TMU0, both, rgb, 0, 8, 5, 3, 2, 0, 0.0f);
  refused(GLIDESHIM_ERR_INVALID_ENUM, GR_TMU0, both, rgb, 0, 8, 5, 3, 0, 2, 0.0f);
  refused(GLIDESHIM_ERR_OUT_OF_RANGE, GR_TMU0, both, rgb, 0, 8, 5, 3, 0, 0, nan);
  refused(GLIDESHIM_ERR_OUT_OF_RANGE, GR_TMU0, both, rgb, 0, 8, 5, 3, 0, 0, 8.0f);
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), kTmuBytes);
  EXPECT_EQ(allocate_small_p8(), 0u);
  expect_no_error();
}

TEST_F(GuTextureManagerTest, ChangeAttributesKeepsTheRecordWhenRefused) {
  const GrMipMapId_t id = allocate_small_p8();
  GrMipMapInfo *info = guTexGetMipMapInfo(id);
  const GrMipMapInfo before = *info;
  auto unchanged = [&](const char *what) {
    EXPECT_EQ(std::memcmp(info, &before, sizeof before), 0) << what;
  };
  EXPECT_EQ(guTexChangeAttributes(id, -1, -1, 6, -1, -1, -1, -1, -1, -1, -1, -1), FXFALSE);
  expect_refused(GLIDESHIM_ERR_INVALID_ENUM, "guTexChangeAttributes");
  unchanged("reserved format");
  EXPECT_EQ(guTexChangeAttributes(id, -1, -1, -1, 5, -1, -1, -1, -1, -1, -1, -1), FXFALSE);
  expect_refused(GLIDESHIM_ERR_INVALID_ENUM, "guTexChangeAttributes");
  unchanged("mip-map mode 5");
  EXPECT_EQ(guTexChangeAttributes(id, -1, -1, -1, -1, GR_LOD_128, -1, -1, -1, -1, -1, -1),
            FXFALSE);
  expect_refused(GLIDESHIM_ERR_INCONSISTENT, "guTexChangeAttributes");
  unchanged("smallest LOD above the largest");
  // The chain base stays at 0 - (65536 + 16384): a chain starting at 256 would start below 0.
  EXPECT_EQ(guTexChangeAttributes(id, -1, -1, -1, -1, -1, GR_LOD_256, -1, -1, -1, -1, -1),
            FXFALSE);
  expect_refused(GLIDESHIM_ERR_OUT_OF_RANGE, "guTexChangeAttributes");
  unchanged("chain moved below address 0");

  // A good change: new modes and size, -1 keeping the rest; the registers are rebuilt.
  EXPECT_EQ(guTexChangeAttributes(id, 32, 32, -1, GR_MIPMAP_DISABLE, GR_LOD_8, GR_LOD_32, -1,
                                  GR_TEXTURECLAMP_CLAMP, -1, GR_TEXTUREFILTER_BILINEAR, -1),
            FXTRUE);
  expect_no_error();
  EXPECT_EQ(info->width, 32);
  EXPECT_EQ(info->lod_min, GR_LOD_8);
  EXPECT_EQ(info->lod_max, GR_LOD_32);
  EXPECT_EQ(info->format, GR_TEXFMT_P_8);
  EXPECT_EQ(info->t_clamp_mode, GR_TEXTURECLAMP_WRAP);
  EXPECT_EQ(info->tmu_base_address, before.tmu_base_address);
  // textureMode: P_8 (5 << 8), clamp W, perspective, min bilinear, clamp S.
  EXPECT_EQ(info->tTextureMode, 0x54Bu);
  // tLOD: lodmin and (mip-mapping off) lodmax both 32 (3 << 2, 3 << 8).
  EXPECT_EQ(info->tLOD, 0x30Cu);
}

TEST_F(GuTextureManagerTest, CallsNeedAnOpenWindow) {
  grSstWinClose();
  glideShimClearError();
  EXPECT_EQ(guTexMemQueryAvail(GR_TMU0), 0u);
  expect_refused(GLIDESHIM_ERR_NOT_INITIALIZED, "guTexMemQueryAvail");
  EXPECT_EQ(allocate_small_p8(), GR_NULL_MIPMAP_HANDLE);
  expect_refused(GLIDESHIM_ERR_NOT_INITIALIZED, "guTexAllocateMemory");
  guTexMemReset();
  expect_refused(GLIDESHIM_ERR_NOT_INITIALIZED, "guTexMemReset");
}

}  // namespace
