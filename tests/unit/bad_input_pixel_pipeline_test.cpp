// Bad input, chapters "color combine" (with the gu preset shorthands), "pixel operations" and
// "depth buffer": unknown enums are INVALID_ENUM, and a rejected preset names the preset the
// program called, not the gr* call it forwards to.
#include "bad_input_fixture.h"

#include <string>
#include <utility>

namespace {

using namespace bad_input;

// The gu presets forward to gr* entry points; a rejected preset must still name the function
// the program called, not the one it forwards to.
TEST_F(BadInputTest, RejectedGuPresetsNameThePresetCalled) {
  expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                  {"guTexCombineFunction", [] { guTexCombineFunction(GR_TMU1, GR_TEXTURECOMBINE_DECAL); }},
                  "TMU1");
  grSstWinClose();
  reset_errors();
  expect_all_rejected(
      GLIDESHIM_ERR_NOT_INITIALIZED,
      {{"guColorCombineFunction", [] { guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE); }},
       {"guAlphaSource", [] { guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA); }},
       {"guTexCombineFunction", [] { guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL); }}},
      "no window");
}

// ---- unknown enums ----------------------------------------------------------------------------

TEST_F(BadInputTest, UnknownDepthEnumsAreInvalidEnum) {
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grDepthBufferMode", [] { grDepthBufferMode(5); }},
       {"grDepthBufferMode", [] { grDepthBufferMode(-1); }},
       {"grDepthBufferMode", [] { grDepthBufferMode(0x100); }},
       {"grDepthBufferFunction", [] { grDepthBufferFunction(8); }},
       {"grDepthBufferFunction", [] { grDepthBufferFunction(-1); }}});
}

TEST_F(BadInputTest, UnknownPixelOperationEnumsAreInvalidEnum) {
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grAlphaBlendFunction", [] { grAlphaBlendFunction(GR_BLEND_RESERVED_8, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO); }},
       {"grAlphaBlendFunction", [] { grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_RESERVED_E, GR_BLEND_ONE, GR_BLEND_ZERO); }},
       {"grAlphaBlendFunction", [] { grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ZERO, -1, GR_BLEND_ZERO); }},
       {"grAlphaBlendFunction", [] { grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ZERO, GR_BLEND_ONE, 0x10); }},
       {"grAlphaTestFunction", [] { grAlphaTestFunction(8); }},
       {"grAlphaTestFunction", [] { grAlphaTestFunction(-1); }},
       {"grChromakeyMode", [] { grChromakeyMode(2); }},
       {"grDitherMode", [] { grDitherMode(3); }},
       {"grDitherMode", [] { grDitherMode(-1); }},
       {"grCullMode", [] { grCullMode(3); }},
       {"grCullMode", [] { grCullMode(-1); }}});
}

TEST_F(BadInputTest, UnknownCombineEnumsAreInvalidEnum) {
  using Combine = void (*)(GrCombineFunction_t, GrCombineFactor_t, GrCombineLocal_t, GrCombineOther_t, FxBool);
  const std::pair<const char *, Combine> units[] = {{"grColorCombine", grColorCombine},
                                                    {"grAlphaCombine", grAlphaCombine}};
  for (const auto &unit : units) {
    const Combine f = unit.second;
    const std::string name = unit.first;
    // Bad function (0xa..0xf and 0x11 are gaps in Glide's list).
    for (int function : {0xa, 0xf, 0x11, -1}) {
      expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                      {name, [=] { f(function, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, FXFALSE); }},
                      "function " + std::to_string(function));
    }
    // Bad factor (6, 7 and 0xe are gaps; 0x10 is past the end).
    for (int factor : {6, 7, 0xe, 0x10, -1}) {
      expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                      {name, [=] { f(GR_COMBINE_FUNCTION_SCALE_OTHER, factor, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, FXFALSE); }},
                      "factor " + std::to_string(factor));
    }
    // Bad local.
    for (int local : {3, -1}) {
      expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                      {name, [=] { f(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, local, GR_COMBINE_OTHER_ITERATED, FXFALSE); }},
                      "local " + std::to_string(local));
    }
    // Bad other.
    for (int other : {3, -1}) {
      expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                      {name, [=] { f(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_ITERATED, other, FXFALSE); }},
                      "other " + std::to_string(other));
    }
  }
  // GR_COMBINE_LOCAL_DEPTH exists only for the alpha unit.
  expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                  {"grColorCombine", [] { grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_DEPTH, GR_COMBINE_OTHER_NONE, FXFALSE); }},
                  "local DEPTH in the colour unit");
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grTexCombine", [] { grTexCombine(GR_TMU0, 0xb, GR_COMBINE_FACTOR_ONE, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ONE, FXFALSE, FXFALSE); }},
       {"grTexCombine", [] { grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, 6, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ONE, FXFALSE, FXFALSE); }},
       {"grTexCombine", [] { grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ONE, 0x11, GR_COMBINE_FACTOR_ONE, FXFALSE, FXFALSE); }},
       {"grTexCombine", [] { grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ONE, GR_COMBINE_FUNCTION_LOCAL, 0xe, FXFALSE, FXFALSE); }}});
}

TEST_F(BadInputTest, UnknownGuPresetsAreInvalidEnum) {
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"guColorCombineFunction", [] { guColorCombineFunction(GR_COLORCOMBINE_ONE + 1); }},
       {"guColorCombineFunction", [] { guColorCombineFunction(-1); }},
       {"guTexCombineFunction", [] { guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_ONE + 1); }},
       {"guTexCombineFunction", [] { guTexCombineFunction(GR_TMU0, -1); }},
       {"guAlphaSource", [] { guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA_TIMES_ITERATED_ALPHA + 1); }},
       {"guAlphaSource", [] { guAlphaSource(-1); }}});
}

}  // namespace
