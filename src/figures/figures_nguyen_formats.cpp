// Nguyen 1999's figures 16 and 17: the 16-bit pixel formats (RGB 565 in the frame buffer, ARGB
// 4444 in the texture unit) as diagrams, each layout found by rendering and reading back, not
// taken from the shim's constants.
#include "figures/figures_kit.h"

#include "measure/plot.h"
#include "techniques/light_passes/scene_pass.h"

#include <algorithm>

namespace gs {
namespace {

using figures::check;
using figures::format;
using figures::Words;

}  // namespace

namespace {

// A pixel-layout diagram: one cell per bit (15 on the left), coloured by the field that holds
// it, the field's letter in the cell and the bit's value in `word` underneath.
FigureImage bit_diagram(const char fields[16], FxU16 word) {
  constexpr int kCell = 28, kMargin = 8;
  FigureImage image = figures::filled(16 * kCell + 2 * kMargin, 2 * kCell + 3 * kMargin + 12, 24, 24, 28);
  const unsigned char white[3] = {240, 240, 240};
  for (int i = 0; i < 16; ++i) {
    const int bit = 15 - i;
    std::uint8_t colour[3] = {90, 90, 90};
    switch (fields[bit]) {
      case 'A': colour[0] = colour[1] = colour[2] = 150; break;
      case 'R': colour[0] = 200, colour[1] = 40, colour[2] = 40; break;
      case 'G': colour[0] = 40, colour[1] = 160, colour[2] = 40; break;
      case 'B': colour[0] = 50, colour[1] = 70, colour[2] = 210; break;
      default: break;
    }
    const int x0 = kMargin + i * kCell, y0 = kMargin;
    for (int y = y0 + 1; y < y0 + kCell - 1; ++y) {
      for (int x = x0 + 1; x < x0 + kCell - 1; ++x) {
        for (int c = 0; c < 3; ++c) image.rgb[static_cast<std::size_t>((y * image.width + x) * 3 + c)] = colour[c];
      }
    }
    const std::string letter(1, fields[bit]);
    draw_bitmap_text(image.rgb, image.width, image.height, x0 + (kCell - 6) / 2, y0 + (kCell - 10) / 2,
                     letter, 2, white);
    const std::string value = (word >> bit) & 1 ? "1" : "0";
    draw_bitmap_text(image.rgb, image.width, image.height, x0 + (kCell - 6) / 2, y0 + kCell + kMargin,
                     value, 2, white);
    const std::string index = std::to_string(bit);
    draw_bitmap_text(image.rgb, image.width, image.height,
                     x0 + (kCell - bitmap_text_width(index, 1)) / 2, y0 + 2 * kCell + kMargin, index, 1,
                     white);
  }
  return image;
}

std::string field_string(const char fields[16]) {
  std::string text;
  for (int bit = 15; bit >= 0; --bit) text += fields[bit];
  return text;
}

// The word a colour becomes in the 565 frame buffer, cleared to it and read back.
FxU16 framebuffer_word(GrColor_t argb, GrBuffer_t buffer) {
  grBufferClear(argb, 0, 0);
  return figures::read_back(1, 1, buffer).at(0, 0);
}

}  // namespace

void figure_nguyen_16(Figure &figure, FigureFault fault) {
  // The layout as the frame buffer stores it: which bits pure red, green and blue set.
  const GrBuffer_t buffer = fault == FigureFault::WrongBuffer ? GR_BUFFER_AUXBUFFER : GR_BUFFER_BACKBUFFER;
  char fields[16];
  const FxU16 red = framebuffer_word(0xFF0000, buffer), green = framebuffer_word(0x00FF00, buffer),
              blue = framebuffer_word(0x0000FF, buffer);
  for (int bit = 0; bit < 16; ++bit) {
    const FxU16 m = static_cast<FxU16>(1u << bit);
    fields[bit] = (red & m) ? 'R' : (green & m) ? 'G' : (blue & m) ? 'B' : '?';
  }
  // Step 1's colour, as the frame buffer holds it.
  grDitherMode(GR_DITHER_DISABLE);
  const FxU16 shadow = framebuffer_word(0x00F00000, buffer);
  figure.image = figures::compose({{bit_diagram(fields, shadow), format("RGB 565: STEP 1 RED 240 = %04X", shadow)}});
  figure.shows = format("The frame buffer's 16-bit pixel as our pipeline stores it, found by clearing "
                        "to pure red, green and blue and reading the words back (%04X, %04X, %04X); "
                        "underneath, the bits of step 1's shadow colour, red 240.",
                        red, green, blue);
  figure.checks.push_back(check("565: red in bits 15-11, green in 10-5, blue in 4-0",
                                field_string(fields) == "RRRRRGGGGGGBBBBB", field_string(fields)));
  figure.checks.push_back(check("the shadow is drawn as 565 red 11110b: the word 111100000000000b (F000)",
                                shadow == 0xF000, format("%04X", shadow)));
}

namespace {

// Draws a 4 x 4 texture of `format` (ARGB_4444 for the figure; texel i, in reading order,
// holds `texels[i]`) point sampled on a 64 x 64 square, once with its colour and once as a
// white mark where its alpha is not 0; returns each texel's colour word and whether its alpha
// was set.
void decode_texels(const FxU16 texels[16], FxU16 colour[16], bool alpha[16], GrTextureFormat_t format) {
  std::vector<FxU16> data(texels, texels + 16);
  GrTexInfo info{GR_LOD_4, GR_LOD_4, GR_ASPECT_1x1, format, data.data()};
  const FxU32 address = grTexMinAddress(GR_TMU0);
  grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_POINT_SAMPLED);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
  grCullMode(GR_CULL_DISABLE);
  grDitherMode(GR_DITHER_DISABLE);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grAlphaCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                 GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  GrVertex v[4] = {};
  const float corners[4][2] = {{0, 0}, {64, 0}, {64, 64}, {0, 64}};
  for (int i = 0; i < 4; ++i) {
    v[i].x = corners[i][0], v[i].y = corners[i][1], v[i].oow = 1.0f;
    v[i].tmuvtx[0].sow = corners[i][0] * 4.0f;
    v[i].tmuvtx[0].tow = corners[i][1] * 4.0f;
  }
  for (int pass = 0; pass < 2; ++pass) {
    grBufferClear(0, 0, 0);
    if (pass == 0) {
      grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                     GR_COMBINE_OTHER_TEXTURE, FXFALSE);
      grAlphaTestFunction(GR_CMP_ALWAYS);
    } else {
      grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                     GR_COMBINE_OTHER_NONE, FXFALSE);
      grConstantColorValue(0xFFFFFFFFu);
      grAlphaTestFunction(GR_CMP_GREATER);
      grAlphaTestReferenceValue(0);
    }
    grDrawTriangle(&v[0], &v[1], &v[2]);
    grDrawTriangle(&v[0], &v[2], &v[3]);
    const Words words = figures::read_back(64, 64);
    for (int i = 0; i < 16; ++i) {
      const FxU16 w = words.at((i % 4) * 16 + 8, (i / 4) * 16 + 8);
      if (pass == 0) colour[i] = w;
      else alpha[i] = w != 0;
    }
  }
  grAlphaTestFunction(GR_CMP_ALWAYS);
  set_scene_state();
}

}  // namespace

void figure_nguyen_17(Figure &figure, FigureFault fault) {
  const GrTextureFormat_t texture_format = fault == FigureFault::WrongFormat ? GR_TEXFMT_ARGB_1555 : GR_TEXFMT_ARGB_4444;
  // The layout as the texture unit decodes it: one texel per bit, each with only that bit set.
  FxU16 single[16], colour[16];
  bool alpha[16];
  for (int bit = 0; bit < 16; ++bit) single[bit] = static_cast<FxU16>(1u << bit);
  decode_texels(single, colour, alpha, texture_format);
  char fields[16];
  for (int bit = 0; bit < 16; ++bit) {
    fields[bit] = alpha[bit] ? 'A' : (colour[bit] & 0xF800) ? 'R' : (colour[bit] & 0x07E0) ? 'G'
                                   : (colour[bit] & 0x001F) ? 'B' : '?';
  }
  // Step 1's word F000 read as ARGB_4444: its alpha and its colour.
  FxU16 shadow_texels[16], shadow_colour[16];
  bool shadow_alpha[16];
  std::fill(shadow_texels, shadow_texels + 16, static_cast<FxU16>(0xF000));
  decode_texels(shadow_texels, shadow_colour, shadow_alpha, texture_format);
  figure.image = figures::compose({{bit_diagram(fields, 0xF000), "ARGB 4444: THE SAME WORD F000"}});
  figure.shows = "The 16-bit ARGB_4444 texel as our texture unit decodes it, found by drawing a "
                 "texture whose texels each hold one set bit and seeing which of alpha, red, green "
                 "and blue it lit; underneath, step 1's word F000 again.";
  figure.checks.push_back(check("4444: alpha in bits 15-12, red 11-8, green 7-4, blue 3-0",
                                field_string(fields) == "AAAARRRRGGGGBBBB", field_string(fields)));
  figure.checks.push_back(check(
      "565 red 11110b read as 4444 is alpha 1111b with a black colour: the shadow mask",
      shadow_alpha[0] && shadow_colour[0] == 0,
      format("alpha %s, colour word %04X", shadow_alpha[0] ? "set" : "clear", shadow_colour[0])));
}

}  // namespace gs
