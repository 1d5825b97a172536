/* state_round_trip: three panels drawn with the same triangles. The left panel uses a state
 * with fog, alpha blending, chroma key and a W buffer; grGlideGetState saves it; the middle
 * panel is drawn after grDisableAllEffects and other changes; grGlideSetState restores the
 * saved state for the right panel, which must look exactly like the left one. */
#include "sdk_common.h"

static void panel(float x0) {
  int k;
  for (k = 0; k < 4; ++k) {
    const float w = 1.5f + 6.0f * (float)k;
    GrVertex a = sdk_vertex(x0 + 5 + 12 * (float)k, 30, w, 250, 200 - 40 * (float)k, 60, 80 + 50 * (float)k);
    GrVertex b = sdk_vertex(x0 + 95, 60 + 25 * (float)k, w, 40, 90, 250, 80 + 50 * (float)k);
    GrVertex c = sdk_vertex(x0 + 20 + 10 * (float)k, 210, w, 60 + 60 * (float)k, 250, 90, 80 + 50 * (float)k);
    grDrawTriangle(&a, &b, &c);
  }
  /* A triangle in the chroma key's colour: keyed out while the key is on. */
  {
    GrVertex a = sdk_vertex(x0 + 60, 150, 2, 0, 255, 0, 255), b = sdk_vertex(x0 + 100, 150, 2, 0, 255, 0, 255);
    GrVertex c = sdk_vertex(x0 + 80, 230, 2, 0, 255, 0, 255);
    grDrawTriangle(&a, &b, &c);
  }
}

int main(int argc, char **argv) {
  GrFog_t table[GR_FOG_TABLE_SIZE];
  GrState saved;
  int frame, frames;
  if (!sdk_open("state_round_trip", argc, argv, &frames)) return 1;
  for (frame = 0; frame < frames; ++frame) {
    grClipWindow(0, 0, 320, 240);
    grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER); /* before the clear: its depth is a W code */
    grDepthMask(FXTRUE);
    grBufferClear(0x00201810, 0, GR_WDEPTHVALUE_FARTHEST);

    guFogGenerateLinear(table, 1.0f, 30.0f);
    grFogTable(table);
    grFogColorValue(0x00806040);
    grFogMode(GR_FOG_WITH_TABLE);
    guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
    grChromakeyValue(0x0000FF00); /* green */
    grChromakeyMode(GR_CHROMAKEY_ENABLE);
    grDepthBufferFunction(GR_CMP_LESS);
    grDitherMode(GR_DITHER_2x2);
    grClipWindow(0, 0, 106, 240);
    panel(0);
    grGlideGetState(&saved);

    grDisableAllEffects();
    grDitherMode(GR_DITHER_DISABLE);
    guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
    grClipWindow(107, 0, 213, 240);
    panel(107);

    grGlideSetState(&saved);
    grClipWindow(214, 0, 320, 240); /* the only setting changed after the restore */
    panel(214);
    grBufferSwap(1);
  }
  return sdk_close();
}
