// Bad input, chapter "texture mapping" (state, sources, downloads): unknown enums, inconsistent
// or out-of-table LODs, unknown aspects and reserved formats, misaligned or overrunning
// addresses, TMUs other than TMU0; a rejected download leaves TMU memory unchanged.
#include "bad_input_fixture.h"

#include <string>
#include <utility>
#include <vector>

namespace {

using namespace bad_input;

// Every entry point that takes a texture description, given `info` and `address`.
std::vector<BadCall> texture_calls(const GrTexInfo &info, FxU32 address) {
  std::vector<BadCall> calls;
  calls.push_back({"grTexSource", [=] {
                     GrTexInfo copy = info;
                     grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &copy);
                   }});
  calls.push_back({"grTexDownloadMipMap", [=] {
                     GrTexInfo copy = info;
                     grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &copy);
                   }});
  calls.push_back({"grTexDownloadMipMapLevel", [=] {
                     grTexDownloadMipMapLevel(GR_TMU0, address, info.smallLod, info.largeLod,
                                              info.aspectRatio, info.format,
                                              GR_MIPMAPLEVELMASK_BOTH, info.data);
                   }});
  return calls;
}

// The two size queries, which must answer 0 for a bad description.
std::vector<BadCall> size_calls(const GrTexInfo &info) {
  return {
      {"grTexCalcMemRequired",
       [=] {
         EXPECT_EQ(grTexCalcMemRequired(info.smallLod, info.largeLod, info.aspectRatio, info.format),
                   0u);
       }},
      {"grTexTextureMemRequired",
       [=] {
         GrTexInfo copy = info;
         EXPECT_EQ(grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &copy), 0u);
       }},
  };
}

TEST_F(BadInputTest, UnknownTextureStateEnumsAreInvalidEnum) {
  GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grTexClampMode", [] { grTexClampMode(GR_TMU0, 2, GR_TEXTURECLAMP_WRAP); }},
       {"grTexClampMode", [] { grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, -1); }},
       {"grTexFilterMode", [] { grTexFilterMode(GR_TMU0, 2, GR_TEXTUREFILTER_BILINEAR); }},
       {"grTexFilterMode", [] { grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, 5); }},
       {"grTexMipMapMode", [] { grTexMipMapMode(GR_TMU0, 3, FXFALSE); }},
       {"grTexMipMapMode", [] { grTexMipMapMode(GR_TMU0, -1, FXTRUE); }},
       {"grTexSource", [=]() mutable { grTexSource(GR_TMU0, 0, 0, &info); }},
       {"grTexSource", [=]() mutable { grTexSource(GR_TMU0, 0, 4, &info); }},
       {"grTexDownloadMipMap", [=]() mutable { grTexDownloadMipMap(GR_TMU0, 0, 0, &info); }},
       {"grTexTextureMemRequired", [=]() mutable { EXPECT_EQ(grTexTextureMemRequired(8, &info), 0u); }}});
}

// ---- texture descriptions ----------------------------------------------------------------------

TEST_F(BadInputTest, SmallLodLargerThanLargeLodIsInconsistent) {
  // smallLod must be >= largeLod (GR_LOD_256 = 0 is the largest level).
  const GrTexInfo reversed = tex_info(GR_LOD_256, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  expect_all_rejected(GLIDESHIM_ERR_INCONSISTENT, texture_calls(reversed, 0), "256 < 1");
  expect_all_rejected(GLIDESHIM_ERR_INCONSISTENT, size_calls(reversed), "256 < 1");
  const GrTexInfo off_by_one = tex_info(GR_LOD_32, GR_LOD_16, GR_ASPECT_2x1, GR_TEXFMT_ALPHA_8);
  expect_all_rejected(GLIDESHIM_ERR_INCONSISTENT, texture_calls(off_by_one, 0), "32 < 16");
  expect_all_rejected(GLIDESHIM_ERR_INCONSISTENT, size_calls(off_by_one), "32 < 16");
}

TEST_F(BadInputTest, LodOutsideTheTableIsInvalidEnum) {
  const std::pair<int, int> cases[] = {{9, GR_LOD_1}, {GR_LOD_1, -1}, {-1, -1}, {9, 9},
                                       {GR_LOD_256, -1}, {0x100, GR_LOD_256}};
  for (const auto &lods : cases) {
    const GrTexInfo info = tex_info(lods.first, lods.second, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
    const std::string what = "small " + std::to_string(lods.first) + " large " + std::to_string(lods.second);
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, texture_calls(info, 0), what);
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, size_calls(info), what);
  }
}

TEST_F(BadInputTest, UnknownAspectIsInvalidEnum) {
  for (int aspect : {GR_ASPECT_1x8 + 1, -1, 0x10}) {
    const GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, aspect, GR_TEXFMT_RGB_565);
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, texture_calls(info, 0), "aspect " + std::to_string(aspect));
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, size_calls(info), "aspect " + std::to_string(aspect));
  }
}

TEST_F(BadInputTest, ReservedTextureFormatsAreInvalidEnum) {
  for (int format : {GR_TEXFMT_RSVD0, GR_TEXFMT_RSVD1, GR_TEXFMT_RSVD2, 0x10, -1}) {
    const GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, format);
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, texture_calls(info, 0), "format " + std::to_string(format));
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, size_calls(info), "format " + std::to_string(format));
  }
}

TEST_F(BadInputTest, PaletteAndNccFormatsAreAccepted) {
  // They read through grTexDownloadTable's tables (tests/numeric/texture_formats_test.cpp).
  for (int format : {GR_TEXFMT_YIQ_422, GR_TEXFMT_P_8, GR_TEXFMT_AYIQ_8422, GR_TEXFMT_AP_88}) {
    const GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, format);
    for (const BadCall &call : texture_calls(info, 0)) {
      call.call();
      SCOPED_TRACE(call.function + " format " + std::to_string(format));
      expect_no_error_reported();
    }
  }
}

TEST_F(BadInputTest, StartAddressNotEightByteAlignedIsOutOfRange) {
  const GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  for (FxU32 address : {1u, 4u, 7u, 0x1000u + 2u}) {
    expect_all_rejected(GLIDESHIM_ERR_OUT_OF_RANGE, texture_calls(info, address),
                        "address " + std::to_string(address));
  }
}

TEST_F(BadInputTest, TextureRunningPastTmuMemoryIsOutOfRange) {
  const FxU32 max = grTexMaxAddress(GR_TMU0);
  expect_no_error_reported();
  // 256x256 565 = 131072 bytes cannot start at the highest start address, nor anywhere its end
  // passes the 2 MB of TMU memory.
  const GrTexInfo big = tex_info(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  const FxU32 tmu_bytes = 2u * 1024u * 1024u;
  for (FxU32 address : {max, tmu_bytes - 131072u + 8u, tmu_bytes, 0xFFFFFFF8u, 0x80000000u}) {
    expect_all_rejected(GLIDESHIM_ERR_OUT_OF_RANGE, texture_calls(big, address),
                        "256x256 565 at " + std::to_string(address));
  }
  // A whole chain 256..1 (174768 bytes) just past the end.
  const GrTexInfo chain = tex_info(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  expect_all_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                      {texture_calls(chain, tmu_bytes - 174768u + 8u)[0],
                       texture_calls(chain, tmu_bytes - 174768u + 8u)[1]},
                      "chain past the end");
  // The smallest texture (8 bytes after rounding) fits exactly at the highest start address;
  // 8 bytes further it does not.
  const GrTexInfo tiny = tex_info(GR_LOD_1, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  expect_all_rejected(GLIDESHIM_ERR_OUT_OF_RANGE, texture_calls(tiny, max + 8u), "1x1 after max");
  reset_errors();
  GrTexInfo copy = tiny;
  grTexDownloadMipMap(GR_TMU0, max, GR_MIPMAPLEVELMASK_BOTH, &copy);
  grTexSource(GR_TMU0, max, GR_MIPMAPLEVELMASK_BOTH, &copy);
  expect_no_error_reported();
  EXPECT_EQ(current().tmu.source.address, max);
}

TEST_F(BadInputTest, TmuOtherThanTmu0IsOutOfRange) {
  GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  for (GrChipID_t tmu : {GR_TMU1, GR_TMU2, GR_FBI, -1}) {
    expect_all_rejected(
        GLIDESHIM_ERR_OUT_OF_RANGE,
        {{"grTexSource", [=]() mutable { grTexSource(tmu, 0, GR_MIPMAPLEVELMASK_BOTH, &info); }},
         {"grTexDownloadMipMap", [=]() mutable { grTexDownloadMipMap(tmu, 0, GR_MIPMAPLEVELMASK_BOTH, &info); }},
         {"grTexDownloadMipMapLevel",
          [=] { grTexDownloadMipMapLevel(tmu, 0, GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, info.data); }},
         {"grTexClampMode", [=] { grTexClampMode(tmu, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP); }},
         {"grTexFilterMode", [=] { grTexFilterMode(tmu, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR); }},
         {"grTexMipMapMode", [=] { grTexMipMapMode(tmu, GR_MIPMAP_NEAREST, FXFALSE); }},
         {"grTexLodBiasValue", [=] { grTexLodBiasValue(tmu, 1.0f); }},
         {"grTexCombine",
          [=] { grTexCombine(tmu, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, FXFALSE, FXFALSE); }},
         {"grTexMinAddress", [=] { EXPECT_EQ(grTexMinAddress(tmu), 0u); }},
         {"grTexMaxAddress", [=] { EXPECT_EQ(grTexMaxAddress(tmu), 0u); }}},
        "TMU " + std::to_string(tmu));
  }
}

TEST_F(BadInputTest, RejectedDownloadLeavesTmuMemoryUnchanged) {
  // Put a known pattern at the start and the end of TMU memory first.
  const FxU32 tmu_bytes = 2u * 1024u * 1024u;
  std::vector<FxU8> pattern(131072);
  for (std::size_t i = 0; i < pattern.size(); ++i) pattern[i] = static_cast<FxU8>(i * 7 + 3);
  GrTexInfo good{GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, pattern.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &good);
  grTexDownloadMipMap(GR_TMU0, tmu_bytes - 131072u, GR_MIPMAPLEVELMASK_BOTH, &good);
  expect_no_error_reported();
  const std::vector<FxU8> memory = current().tmu.memory;
  ASSERT_EQ(memory.size(), tmu_bytes);
  ASSERT_EQ(memory[0], pattern[0]);
  ASSERT_EQ(memory[tmu_bytes - 1], pattern.back());

  // Rejected downloads of 0xAB bytes over both patterns.
  GrTexInfo big = tex_info(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  GrTexInfo chain = tex_info(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  GrTexInfo reversed = tex_info(GR_LOD_256, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  GrTexInfo reserved = tex_info(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RSVD2);
  const std::vector<std::pair<GlideShimError, BadCall>> calls = {
      {GLIDESHIM_ERR_OUT_OF_RANGE, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, tmu_bytes - 65536u, GR_MIPMAPLEVELMASK_BOTH, &big); }}},
      // Only the odd levels (128, 32, 8, 2) run past the end: 34952 bytes from 2 MB - 32768.
      {GLIDESHIM_ERR_OUT_OF_RANGE, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, tmu_bytes - 32768u, GR_MIPMAPLEVELMASK_ODD, &chain); }}},
      {GLIDESHIM_ERR_OUT_OF_RANGE, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, 4, GR_MIPMAPLEVELMASK_BOTH, &big); }}},
      {GLIDESHIM_ERR_OUT_OF_RANGE, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU1, 0, GR_MIPMAPLEVELMASK_BOTH, &big); }}},
      {GLIDESHIM_ERR_INCONSISTENT, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &reversed); }}},
      {GLIDESHIM_ERR_INVALID_ENUM, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &reserved); }}},
      // Rows 200..256 of a 256-row level: the last row does not exist.
      {GLIDESHIM_ERR_OUT_OF_RANGE,
       {"grTexDownloadMipMapLevelPartial",
        [&] { grTexDownloadMipMapLevelPartial(GR_TMU0, 0, GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, big.data, 200, 256); }}},
      {GLIDESHIM_ERR_OUT_OF_RANGE,
       {"grTexDownloadMipMapLevel",
        [&] { grTexDownloadMipMapLevel(GR_TMU0, tmu_bytes - 8u, GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, big.data); }}},
      // Level 1x1 of a chain whose offset alone (174760 bytes) passes the end.
      {GLIDESHIM_ERR_OUT_OF_RANGE,
       {"grTexDownloadMipMapLevel",
        [&] { grTexDownloadMipMapLevel(GR_TMU0, tmu_bytes - 8u, GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, big.data); }}},
  };
  for (const auto &call : calls) {
    expect_rejected(call.first, call.second);
    ASSERT_TRUE(current().tmu.memory == memory) << "TMU memory changed by a rejected "
                                                << call.second.function;
  }
}

}  // namespace
