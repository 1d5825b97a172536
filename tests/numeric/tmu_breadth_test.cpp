// The TMU's detail factor (grTexDetailControl), the ITRGB lighting override
// (grAlphaControlsITRGBLighting), the delta0 iterated colour (grConstantColorValue4 with the
// *_DELTA0 presets) and grTexCombineFunction, each against the CPU Voodoo reference per pixel;
// bad arguments refused with the state unchanged; the new state through grGlideGetState/SetState.
#include "glide_window.h"
#include "voodoo_reference.h"

#include "context.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using glide_shim::current;

using Plane = TexturePlane;  // see glide_window.h

class TmuBreadthTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grDitherMode(GR_DITHER_DISABLE);  // the reference models the truncating write
    guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
    grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP);
  }

  // A full 256..1 chain of one texel value at address 0, mip-mapped.
  static void load_uniform_chain(FxU16 texel) {
    static std::vector<FxU16> texels;
    texels.assign(256 * 256 * 2, texel);
    GrTexInfo info{GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
    grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  }

  // The hardware's LOD at the centre of row y in 8.8 before the clamp (no bias, no dither), and
  // the distance of the unrounded value from an 8.8 step, where float and fixed point may part.
  static int model_lod_88(const Plane &plane, int y, double &distance) {
    const double gradient = std::max(plane.s_dx * plane.s_dx, plane.t_dy * plane.t_dy);
    const double lod = 0.5 * std::log2(gradient) - std::log2(plane.oow(y + 0.5));
    const double steps = lod * 256.0;
    distance = std::abs(steps - std::round(steps));
    return static_cast<int>(std::floor(steps));
  }

  static voodoo_ref::Rgba rgb565(FxU16 word) { return voodoo_ref::unpack_rgb565(word); }
};

// --- grTexDetailControl -----------------------------------------------------------------------

TEST_F(TmuBreadthTest, DetailFactorFollowsTheLodPerPixel) {
  // A grey chain, so the level does not matter: BLEND_LOCAL with the detail factor,
  // ((0 - t) * (f + 1) >> 8) + t, shows f in every channel. The floor runs from LOD 0.58 at the
  // top to 5.6 at the bottom; detail bias 4 gives a factor above zero on the upper rows only.
  const FxU16 grey = 0xBDF7;  // 565 (23, 47, 23)
  load_uniform_chain(grey);
  const Plane floor{1.5, 1.5, 1.0, 1.0 / 32.0};
  const voodoo_ref::TexCombineConfig blend_local{
      GR_COMBINE_FUNCTION_BLEND_LOCAL, GR_COMBINE_FACTOR_DETAIL_FACTOR,
      GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, false, false};
  grTexCombine(GR_TMU0, blend_local.rgb_function, blend_local.rgb_factor,
               blend_local.alpha_function, blend_local.alpha_factor, FXFALSE, FXFALSE);
  struct Setting {
    int bias, scale;
    float max;
  };
  for (const Setting &setting : {Setting{4, 6, 1.0f}, Setting{4, 7, 0.5f}, Setting{3, 2, 0.9f},
                                 Setting{-2, 7, 1.0f}, Setting{6, 0, 1.0f}}) {
    SCOPED_TRACE("bias " + std::to_string(setting.bias) + " scale " +
                 std::to_string(setting.scale) + " max " + std::to_string(setting.max));
    grTexDetailControl(GR_TMU0, setting.bias, static_cast<FxU8>(setting.scale), setting.max);
    draw_plane(floor);
    const std::vector<FxU16> frame = read_buffer();
    const int max_field = voodoo_ref::detail_max_field(setting.max);
    int compared = 0, wrong = 0, nonzero = 0;
    for (int y = 0; y < kHeight; ++y) {
      double distance = 0.0;
      const int lod = std::clamp(model_lod_88(floor, y, distance), 0, 8 * 256);
      if (distance < 0.02) continue;  // float and 8.8 may round to neighbouring steps
      const int f = voodoo_ref::detail_factor(lod, setting.bias, setting.scale, max_field);
      nonzero += f > 0;
      const FxU16 want = voodoo_ref::pack_rgb565(
          voodoo_ref::combine_tmu(blend_local, rgb565(grey), voodoo_ref::kNoUpstreamTmu, f, 0));
      for (int x = 0; x < kWidth; ++x) {
        ++compared;
        const FxU16 got = frame[static_cast<std::size_t>(y * kWidth + x)];
        if (got != want && ++wrong <= 3) {
          ADD_FAILURE() << "pixel (" << x << ", " << y << "): LOD " << lod << "/256, factor " << f
                        << ": want " << want << ", got " << got;
        }
      }
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(compared, kWidth * kHeight / 2);
    if (setting.bias > 0) {
      EXPECT_GT(nonzero, 0);
    }
  }
  expect_no_error();
}

TEST_F(TmuBreadthTest, DetailFactorAtAFixedLodMatchesTheRegisterArithmetic) {
  // One 1/w, one gradient: the LOD is the same on every pixel, log2(6) = 661/256 in 8.8. The
  // DETAIL preset (BLEND with ONE_MINUS_DETAIL_FACTOR) and DETAIL_OTHER, for a range of fields.
  const FxU16 white = 0xFFFF;
  load_uniform_chain(white);
  const Plane flat{6.0, 6.0, 1.0, 1.0};
  const int lod = 661;
  int distinct_outputs = 0;
  FxU16 previous = 0;
  for (GrTextureCombineFnc_t preset : {GR_TEXTURECOMBINE_DETAIL, GR_TEXTURECOMBINE_DETAIL_OTHER}) {
    grTexCombineFunction(GR_TMU0, preset);
    for (int bias : {-32, 0, 2, 3, 5, 31}) {
      for (int scale : {0, 3, 7}) {
        for (float max : {0.0f, 0.3f, 1.0f}) {
          grTexDetailControl(GR_TMU0, bias, static_cast<FxU8>(scale), max);
          draw_plane(flat);
          const int f = voodoo_ref::detail_factor(lod, bias, scale, voodoo_ref::detail_max_field(max));
          const auto &c = current().tmu.combine;
          const voodoo_ref::TexCombineConfig config{c.rgb_function, c.rgb_factor, c.alpha_function,
                                                    c.alpha_factor, c.rgb_invert, c.alpha_invert};
          const FxU16 want = voodoo_ref::pack_rgb565(
              voodoo_ref::combine_tmu(config, rgb565(white), voodoo_ref::kNoUpstreamTmu, f, 0));
          for (FxU16 got : read_buffer()) {
            ASSERT_EQ(got, want) << "preset " << preset << " bias " << bias << " scale " << scale
                                 << " max " << max << " factor " << f;
          }
          distinct_outputs += want != previous;
          previous = want;
        }
      }
    }
  }
  EXPECT_GT(distinct_outputs, 6);  // the factor really moves the picture
  expect_no_error();
}

TEST_F(TmuBreadthTest, DetailFactorWithoutMipmappingUsesLodmin) {
  // GR_MIPMAP_DISABLE: lodmin == lodmax == largeLod (GR_LOD_64 = 2), bias 5: (5 - 2) << 4 = 48.
  std::vector<FxU16> texels(64 * 64, 0xFFFF);
  GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  const voodoo_ref::TexCombineConfig blend_local{
      GR_COMBINE_FUNCTION_BLEND_LOCAL, GR_COMBINE_FACTOR_DETAIL_FACTOR,
      GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, false, false};
  grTexCombine(GR_TMU0, blend_local.rgb_function, blend_local.rgb_factor,
               blend_local.alpha_function, blend_local.alpha_factor, FXFALSE, FXFALSE);
  grTexDetailControl(GR_TMU0, 5, 4, 1.0f);
  draw_plane(Plane{4.0, 4.0, 1.0, 0.25});
  EXPECT_EQ(voodoo_ref::detail_factor(2 * 256, 5, 4, 255), 48);
  const FxU16 want = voodoo_ref::pack_rgb565(voodoo_ref::combine_tmu(
      blend_local, rgb565(0xFFFF), voodoo_ref::kNoUpstreamTmu, 48, 0));
  for (FxU16 got : read_buffer()) ASSERT_EQ(got, want);
  expect_no_error();
}

TEST_F(TmuBreadthTest, BadDetailArgumentsAreRefusedAndChangeNothing) {
  grTexDetailControl(GR_TMU0, -7, 3, 0.5f);
  expect_no_error();
  const auto before = current().tmu;
  struct Call {
    GrChipID_t tmu;
    int bias;
    int scale;
    float max;
    GlideShimError error;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const Call &call : {Call{GR_TMU0, -33, 0, 0.5f, GLIDESHIM_ERR_OUT_OF_RANGE},
                           Call{GR_TMU0, 32, 0, 0.5f, GLIDESHIM_ERR_OUT_OF_RANGE},
                           Call{GR_TMU0, 0, 8, 0.5f, GLIDESHIM_ERR_OUT_OF_RANGE},
                           Call{GR_TMU0, 0, 255, 0.5f, GLIDESHIM_ERR_OUT_OF_RANGE},
                           Call{GR_TMU0, 0, 0, -0.01f, GLIDESHIM_ERR_OUT_OF_RANGE},
                           Call{GR_TMU0, 0, 0, 1.01f, GLIDESHIM_ERR_OUT_OF_RANGE},
                           Call{GR_TMU0, 0, 0, nan, GLIDESHIM_ERR_OUT_OF_RANGE},
                           Call{GR_TMU1, 0, 0, 0.5f, GLIDESHIM_ERR_OUT_OF_RANGE}}) {
    glideShimClearError();
    grTexDetailControl(call.tmu, call.bias, static_cast<FxU8>(call.scale), call.max);
    EXPECT_EQ(glideShimGetLastError(), call.error) << call.bias << " " << call.scale << " " << call.max;
    EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("grTexDetailControl"),
              std::string::npos);
    EXPECT_EQ(current().tmu.detail_bias, before.detail_bias);
    EXPECT_EQ(current().tmu.detail_scale, before.detail_scale);
    EXPECT_EQ(current().tmu.detail_max, before.detail_max);
  }
  EXPECT_EQ(current().tmu.detail_bias, -7);
  EXPECT_EQ(current().tmu.detail_scale, 3);
  EXPECT_EQ(current().tmu.detail_max, 127);  // (FxU32)(0.5f * 255.0f)
}

// --- grAlphaControlsITRGBLighting ------------------------------------------------------------

// One 1x1 quad per pixel with its own iterated colour over an AI_88 texture of random alpha and
// intensity, texel (x, y) under pixel (x, y).
class ItrgbLightingTest : public TmuBreadthTest {
 protected:
  void SetUp() override {
    TmuBreadthTest::SetUp();
    std::mt19937 random(77);
    std::uniform_int_distribution<int> byte(0, 255);
    texels_.resize(kWidth * kHeight);
    iterated_.resize(kWidth * kHeight);
    for (int i = 0; i < kWidth * kHeight; ++i) {
      texels_[static_cast<std::size_t>(i)] = static_cast<FxU16>(byte(random) << 8 | byte(random));
      iterated_[static_cast<std::size_t>(i)] = {byte(random), byte(random), byte(random), byte(random)};
    }
    GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_ALPHA_INTENSITY_88, texels_.data()};
    grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
    guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
    grConstantColorValue(0xFF2080E0u);
    constant_ = {0x20, 0x80, 0xE0, 0xFF};
    expect_no_error();
  }

  void draw_pixels() {
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const voodoo_ref::Rgba &c = iterated_[static_cast<std::size_t>(y * kWidth + x)];
        GrVertex style = vertex();
        style.r = static_cast<float>(c.r), style.g = static_cast<float>(c.g);
        style.b = static_cast<float>(c.b), style.a = static_cast<float>(c.a);
        GrVertex v[4];
        const float xs[4] = {0, 1, 1, 0}, ys[4] = {0, 0, 1, 1};
        for (int k = 0; k < 4; ++k) {
          v[k] = style;
          v[k].x = static_cast<float>(x) + xs[k];
          v[k].y = static_cast<float>(y) + ys[k];
          v[k].tmuvtx[0].sow = 4.0f * v[k].x;  // 64 texels span s = 0..256
          v[k].tmuvtx[0].tow = 4.0f * v[k].y;
        }
        grDrawTriangle(&v[0], &v[1], &v[2]);
        grDrawTriangle(&v[0], &v[2], &v[3]);
      }
    }
  }

  // Every pixel against the reference's colour unit; returns the number of pixels whose texel
  // alpha had bit 7 set (the override picks the constant colour there).
  int expect_frame(const voodoo_ref::CombineConfig &color, bool override_on) {
    const voodoo_ref::CombineConfig alpha{GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
                                          GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_NONE, false};
    const std::vector<FxU16> frame = read_buffer();
    int high_alpha = 0, wrong = 0;
    for (int i = 0; i < kWidth * kHeight; ++i) {
      voodoo_ref::CombineInputs in;
      in.iterated = iterated_[static_cast<std::size_t>(i)];
      in.texture = voodoo_ref::decode_texel(GR_TEXFMT_ALPHA_INTENSITY_88,
                                            texels_[static_cast<std::size_t>(i)]);
      in.constant = constant_;
      in.alpha_controls_itrgb = override_on;
      high_alpha += (in.texture.a & 0x80) != 0;
      const FxU16 want = voodoo_ref::pack_rgb565(voodoo_ref::combine_fbi(color, alpha, in));
      if (frame[static_cast<std::size_t>(i)] != want && ++wrong <= 3) {
        ADD_FAILURE() << "pixel " << i << ": want " << want << ", got "
                      << frame[static_cast<std::size_t>(i)];
      }
    }
    EXPECT_EQ(wrong, 0);
    return high_alpha;
  }

  std::vector<FxU16> texels_;
  std::vector<voodoo_ref::Rgba> iterated_;
  voodoo_ref::Rgba constant_;
};

TEST_F(ItrgbLightingTest, TextureAlphaBitSevenPicksConstantOrIteratedLocal) {
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  // TEXTURE_TIMES_ITRGB: texture * local, where local is now chosen per pixel.
  guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB);
  const voodoo_ref::CombineConfig times{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                                        GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, false};
  grAlphaControlsITRGBLighting(FXTRUE);
  draw_pixels();
  const int high = expect_frame(times, true);
  EXPECT_GT(high, kWidth * kHeight / 4);
  EXPECT_LT(high, kWidth * kHeight * 3 / 4);
  // The override outlives grColorCombine (gglide.c leaves fbzColorPath bit 7 alone), and
  // overrides a constant local as well.
  const voodoo_ref::CombineConfig add{GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL,
                                      GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_CONSTANT,
                                      GR_COMBINE_OTHER_TEXTURE, false};
  grColorCombine(add.function, add.factor, add.local, add.other, FXFALSE);
  draw_pixels();
  expect_frame(add, true);
  // Off again: the local is what grColorCombine says.
  grAlphaControlsITRGBLighting(FXFALSE);
  draw_pixels();
  expect_frame(add, false);
  expect_no_error();
}

TEST_F(ItrgbLightingTest, WithoutTextureTheLocalIsIterated) {
  // No combine reads the TMU: its output is zero, bit 7 clear, so the local is the iterated RGB.
  const voodoo_ref::CombineConfig local{GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
                                        GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_NONE, false};
  grColorCombine(local.function, local.factor, local.local, local.other, FXFALSE);
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  grAlphaControlsITRGBLighting(FXTRUE);
  draw_pixels();
  const std::vector<FxU16> frame = read_buffer();
  for (int i = 0; i < kWidth * kHeight; ++i) {
    ASSERT_EQ(frame[static_cast<std::size_t>(i)],
              voodoo_ref::pack_rgb565(iterated_[static_cast<std::size_t>(i)]))
        << "pixel " << i;
  }
  expect_no_error();
}

// --- grConstantColorValue4 and the delta0 presets --------------------------------------------

TEST_F(TmuBreadthTest, Delta0PresetsIterateTheConstantColorValue4Colour) {
  guAlphaSource(GR_ALPHASOURCE_CC_ALPHA);
  grConstantColorValue(0xFF102030u);
  grConstantColorValue4(255.0f, 10.7f, 200.2f, 99.9f);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB_DELTA0);
  // The vertex colours are not read in delta0 mode (the driver does not send them): NaN is fine.
  GrVertex style = vertex();
  style.r = style.g = style.b = std::numeric_limits<float>::quiet_NaN();
  draw_rect(0, 0, kWidth, kHeight, style);
  const FxU16 flat = voodoo_ref::pack_rgb565({10, 200, 99, 255});
  for (FxU16 got : read_buffer()) ASSERT_EQ(got, flat);
  expect_no_error();
  // A new colour in delta0 mode reaches the next draw; the constant colour is untouched.
  grConstantColorValue4(0.0f, 255.0f, 0.5f, 128.0f);
  draw_rect(0, 0, kWidth, kHeight, style);
  for (FxU16 got : read_buffer()) ASSERT_EQ(got, voodoo_ref::pack_rgb565({255, 0, 128, 255}));
  EXPECT_EQ(current().color_path.constant_color, 0xFF102030u);
  // TEXTURE_TIMES_ITRGB_DELTA0 multiplies the texture by that colour.
  std::vector<FxU16> texels(64 * 64, 0xFFFF);
  GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB_DELTA0);
  draw_rect(0, 0, kWidth, kHeight, style);
  voodoo_ref::CombineInputs in;
  in.iterated = {255, 0, 128, 255};
  in.texture = rgb565(0xFFFF);
  const voodoo_ref::CombineConfig times{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                                        GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, false};
  const voodoo_ref::CombineConfig alpha{GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
                                        GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_NONE, false};
  const FxU16 modulated = voodoo_ref::pack_rgb565(voodoo_ref::combine_fbi(times, alpha, in));
  for (FxU16 got : read_buffer()) ASSERT_EQ(got, modulated);
  // Any other preset leaves delta0 mode: the vertex colour is iterated again.
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  style = vertex();
  style.r = 40.0f, style.g = 80.0f, style.b = 120.0f;
  draw_rect(0, 0, kWidth, kHeight, style);
  for (FxU16 got : read_buffer()) ASSERT_EQ(got, voodoo_ref::pack_rgb565({40, 80, 120, 255}));
  expect_no_error();
}

TEST_F(TmuBreadthTest, BadConstantColorValue4IsRefusedAndChangesNothing) {
  grConstantColorValue4(1.0f, 2.0f, 3.0f, 4.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float bad[][4] = {{-1.0f, 0, 0, 0}, {0, 256.0f, 0, 0}, {0, 0, nan, 0}, {0, 0, 0, inf}};
  for (const auto &value : bad) {
    glideShimClearError();
    grConstantColorValue4(value[0], value[1], value[2], value[3]);
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
    EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("grConstantColorValue4"),
              std::string::npos);
    const float *kept = current().color_path.iterated4;
    EXPECT_EQ(kept[0], 1.0f);
    EXPECT_EQ(kept[1], 2.0f);
    EXPECT_EQ(kept[2], 3.0f);
    EXPECT_EQ(kept[3], 4.0f);
  }
}

// --- grTexCombineFunction -------------------------------------------------------------------

TEST_F(TmuBreadthTest, TexCombineFunctionSetsTheSamePresetsAsGuTexCombineFunction) {
  for (GrTextureCombineFnc_t preset = GR_TEXTURECOMBINE_ZERO; preset <= GR_TEXTURECOMBINE_ONE;
       ++preset) {
    grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, GR_COMBINE_FACTOR_LOCAL,
                 GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, GR_COMBINE_FACTOR_LOCAL, FXTRUE,
                 FXTRUE);
    guTexCombineFunction(GR_TMU0, preset);
    const glide_shim::TexCombineUnit by_gu = current().tmu.combine;
    grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, GR_COMBINE_FACTOR_LOCAL,
                 GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, GR_COMBINE_FACTOR_LOCAL, FXTRUE,
                 FXTRUE);
    grTexCombineFunction(GR_TMU0, preset);
    EXPECT_TRUE(current().tmu.combine == by_gu) << "preset " << preset;
  }
  EXPECT_EQ(current().tmu.combine.rgb_invert, true);  // ONE: ZERO inverted
  expect_no_error();
  const glide_shim::TexCombineUnit kept = current().tmu.combine;
  grTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_ONE + 1);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("grTexCombineFunction"),
            std::string::npos);
  grTexCombineFunction(GR_TMU1, GR_TEXTURECOMBINE_DECAL);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  EXPECT_TRUE(current().tmu.combine == kept);
}

// --- grGlideGetState / grGlideSetState --------------------------------------------------------

TEST_F(TmuBreadthTest, GetStateAndSetStateCarryDetailItrgbAndDelta0) {
  grTexDetailControl(GR_TMU0, -5, 6, 0.75f);
  grAlphaControlsITRGBLighting(FXTRUE);
  grConstantColorValue4(12.5f, 100.25f, 0.0f, 255.0f);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB_DELTA0);
  GrState saved;
  grGlideGetState(&saved);
  grTexDetailControl(GR_TMU0, 20, 1, 0.0f);
  grAlphaControlsITRGBLighting(FXFALSE);
  grConstantColorValue4(0.0f, 0.0f, 0.0f, 0.0f);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  grGlideSetState(&saved);
  expect_no_error();
  const auto &ctx = current();
  EXPECT_EQ(ctx.tmu.detail_bias, -5);
  EXPECT_EQ(ctx.tmu.detail_scale, 6);
  EXPECT_EQ(ctx.tmu.detail_max, 191);  // (FxU32)(0.75f * 255.0f)
  EXPECT_TRUE(ctx.color_path.alpha_controls_itrgb);
  EXPECT_TRUE(ctx.color_path.delta0);
  EXPECT_EQ(ctx.color_path.iterated4[0], 12.5f);
  EXPECT_EQ(ctx.color_path.iterated4[1], 100.25f);
  EXPECT_EQ(ctx.color_path.iterated4[2], 0.0f);
  EXPECT_EQ(ctx.color_path.iterated4[3], 255.0f);
  // And it draws with them: delta0 colour (100, 0, 255).
  GrVertex style = vertex();
  draw_rect(0, 0, kWidth, kHeight, style);
  for (FxU16 got : read_buffer()) ASSERT_EQ(got, voodoo_ref::pack_rgb565({100, 0, 255, 255}));
}

}  // namespace
