/* lfb_formats: grLfbWriteRegion with every source format. Six bands of a red-green ramp,
 * written as 565, 555, 1555, 888, 8888 and 565 + depth; then ZA16 depth codes (near on the
 * left, far on the right) under a Z-buffered blue triangle that is hidden where the written
 * depth is nearer. */
#include "sdk_common.h"

static FxU16 words[320 * 24];
static FxU32 dwords[320 * 24];

int main(int argc, char **argv) {
  int frame, frames, x, y, band;
  if (!sdk_open("lfb_formats", argc, argv, &frames)) return 1;
  for (frame = 0; frame < frames; ++frame) {
    grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
    grDepthBufferFunction(GR_CMP_GREATER); /* larger ooz is nearer */
    grDepthMask(FXTRUE);
    grBufferClear(0x00000000, 0, 0);
    for (band = 0; band < 6; ++band) {
      for (y = 0; y < 24; ++y) {
        for (x = 0; x < 320; ++x) {
          const unsigned r = (unsigned)(x * 255 / 319), g = (unsigned)(y * 255 / 23), b = (unsigned)(band * 40);
          const int i = y * 320 + x;
          switch (band) {
            case 0: words[i] = (FxU16)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3)); break;
            case 1: words[i] = (FxU16)(((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3)); break;
            case 2: words[i] = (FxU16)(0x8000 | ((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3)); break;
            case 3: dwords[i] = (r << 16) | (g << 8) | b; break;
            case 4: dwords[i] = 0xFF000000u | (r << 16) | (g << 8) | b; break;
            default: /* colour low, depth code high: a depth ramp under the band */
              dwords[i] = ((FxU32)(x * 200) << 16) | (((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
              break;
          }
        }
      }
      if (band < 3) {
        grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, (FxU32)(band * 26), (GrLfbSrcFmt_t)band, 320, 24, 640, words);
      } else {
        static const GrLfbSrcFmt_t formats[3] = {GR_LFB_SRC_FMT_888, GR_LFB_SRC_FMT_8888, GR_LFB_SRC_FMT_565_DEPTH};
        grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, (FxU32)(band * 26), formats[band - 3], 320, 24, 1280, dwords);
      }
    }
    /* ZA16: depth codes from near (65535, left) to far (0, right) over the lower area. */
    for (y = 0; y < 24; ++y) {
      for (x = 0; x < 320; ++x) words[y * 320 + x] = (FxU16)(65535 - x * 204);
    }
    for (y = 160; y < 240; y += 24) {
      grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 0, (FxU32)y, GR_LFB_SRC_FMT_ZA16, 320, y + 24 <= 240 ? 24 : 240 - (FxU32)y, 640, words);
    }
    {
      GrVertex a = sdk_vertex(10, 165, 1, 40, 80, 255, 255), b = sdk_vertex(310, 170, 1, 40, 80, 255, 255);
      GrVertex c = sdk_vertex(160, 235, 1, 40, 80, 255, 255);
      a.ooz = b.ooz = c.ooz = 32768.0f; /* visible where the written depth is farther */
      guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
      grDrawTriangle(&a, &b, &c);
    }
    grBufferSwap(1);
  }
  return sdk_close();
}
