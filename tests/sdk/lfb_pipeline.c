/* lfb_pipeline: write locks through the pixel pipeline (grLfbLock with pixelPipeline FXTRUE).
 * Top: a Z-buffered Gouraud quad, then a 565 + depth band written across it with depth codes
 * from near (left) to far (right): the band hides the quad on the left and is hidden on the
 * right. Middle: an 888 band at constant alpha 0x80 blended over a ramp, and an 8888 sprite in
 * ABGR lane order whose magenta background the chroma key drops. Bottom: a red band fogged by
 * the fog table indexed by its written depth codes. */
#include "sdk_common.h"

static FxU16 ramp[320 * 40];

static void lock_pipeline(GrLfbWriteMode_t mode, GrLfbInfo_t *info) {
  info->size = sizeof *info;
  if (!grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, mode, GR_ORIGIN_UPPER_LEFT, FXTRUE, info)) {
    fprintf(stderr, "lfb_pipeline: grLfbLock failed\n");
    exit(1);
  }
}

static FxU32 *row32(GrLfbInfo_t *info, int y) {
  return (FxU32 *)((char *)info->lfbPtr + (size_t)y * info->strideInBytes);
}

int main(int argc, char **argv) {
  int frame, frames, x, y;
  GrFog_t fog[GR_FOG_TABLE_SIZE];
  GrLfbInfo_t info;
  if (!sdk_open("lfb_pipeline", argc, argv, &frames)) return 1;
  guFogGenerateExp(fog, 0.004f);
  for (frame = 0; frame < frames; ++frame) {
    grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
    grDepthBufferFunction(GR_CMP_GREATER); /* larger ooz is nearer */
    grDepthMask(FXTRUE);
    grFogMode(GR_FOG_DISABLE);
    grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
    grChromakeyMode(GR_CHROMAKEY_DISABLE);
    grLfbWriteColorFormat(GR_COLORFORMAT_ARGB);
    grBufferClear(0x00000000, 0, 0);

    /* The quad at ooz 32768, then the band with depth 65535 (left) .. 0 (right). */
    {
      GrVertex a = sdk_vertex(40, 20, 1, 255, 64, 32, 255), b = sdk_vertex(280, 20, 1, 32, 64, 255, 255);
      GrVertex c = sdk_vertex(280, 110, 1, 32, 255, 64, 255), d = sdk_vertex(40, 110, 1, 255, 255, 255, 255);
      a.ooz = b.ooz = c.ooz = d.ooz = 32768.0f;
      guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
      grDrawTriangle(&a, &b, &c);
      grDrawTriangle(&a, &c, &d);
    }
    lock_pipeline(GR_LFBWRITEMODE_565_DEPTH, &info);
    for (y = 45; y < 85; ++y) {
      FxU32 *line = row32(&info, y);
      for (x = 0; x < 320; ++x) {
        const FxU32 code = (FxU32)(65535 - x * 205), g = (FxU32)((y - 45) * 63 / 39);
        line[x] = code << 16 | 0x1F << 11 | g << 5 | 0x08;
      }
    }
    grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER);

    /* A grey ramp, written directly; then constant alpha 0x80 blends an 888 band over it. */
    grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
    grDepthMask(FXFALSE);
    for (y = 0; y < 40; ++y) {
      for (x = 0; x < 320; ++x) {
        const unsigned v = (unsigned)(x * 255 / 319);
        ramp[y * 320 + x] = (FxU16)((v >> 3) << 11 | (v >> 2) << 5 | (v >> 3));
      }
    }
    grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 130, GR_LFB_SRC_FMT_565, 320, 40, 640, ramp);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
    grLfbConstantAlpha(0x80);
    lock_pipeline(GR_LFBWRITEMODE_888, &info);
    for (y = 140; y < 160; ++y) {
      FxU32 *line = row32(&info, y);
      for (x = 0; x < 200; ++x) line[x] = 0x0000A0FFu; /* sky blue: R 0x00, G 0xA0, B 0xFF */
    }
    grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER);

    /* The sprite: a yellow disc on magenta, in ABGR lane order, keyed on magenta. */
    grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
    grChromakeyMode(GR_CHROMAKEY_ENABLE);
    grChromakeyValue(0x00FF00FFu); /* magenta in the window's ABGR */
    grLfbWriteColorFormat(GR_COLORFORMAT_ABGR);
    lock_pipeline(GR_LFBWRITEMODE_8888, &info);
    for (y = 0; y < 40; ++y) {
      FxU32 *line = row32(&info, 130 + y);
      for (x = 0; x < 40; ++x) {
        const int dx = x - 20, dy = y - 20;
        line[240 + x] = dx * dx + dy * dy < 18 * 18 ? 0xFF00FFFFu : 0xFFFF00FFu; /* A B G R */
      }
    }
    grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER);
    grChromakeyMode(GR_CHROMAKEY_DISABLE);
    grLfbWriteColorFormat(GR_COLORFORMAT_ARGB);

    /* Table fog by the written depth code, from near (left) to far (right). */
    grFogTable(fog);
    grFogColorValue(0x00C0C0C0u);
    grFogMode(GR_FOG_WITH_TABLE);
    lock_pipeline(GR_LFBWRITEMODE_565_DEPTH, &info);
    for (y = 190; y < 230; ++y) {
      FxU32 *line = row32(&info, y);
      for (x = 0; x < 320; ++x) line[x] = (FxU32)(x * 205) << 16 | 0xF800;
    }
    grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER);
    grFogMode(GR_FOG_DISABLE);
    grLfbConstantAlpha(0xFF);
    grBufferSwap(1);
  }
  return sdk_close();
}
