/* fog_ramp: table fog on a W-buffered floor receding from w = 1 to w = 200 (guFogGenerateExp,
 * density 0.2), and below it two bars fogged by iterated alpha (0 to 255) and iterated Z, with
 * MULT2 on the lower half of the Z bar. */
#include "sdk_common.h"

/* One band of the floor between screen rows y0 and y1 (parameter t0, t1 down the floor), with
 * 1/w linear in t as a perspective floor has it, and the colour fading from orange to green. */
static void floor_strip(float t0, float t1) {
  const float y0 = 10.0f + 150.0f * t0, y1 = 10.0f + 150.0f * t1;
  const float w0 = 200.0f / (1.0f + 199.0f * t0), w1 = 200.0f / (1.0f + 199.0f * t1);
  GrVertex a = sdk_vertex(0, y0, w0, 200 - 140 * t0, 120 + 80 * t0, 60 + 30 * t0, 255);
  GrVertex b = sdk_vertex(320, y0, w0, 200 - 140 * t0, 120 + 80 * t0, 60 + 30 * t0, 255);
  GrVertex c = sdk_vertex(320, y1, w1, 200 - 140 * t1, 120 + 80 * t1, 60 + 30 * t1, 255);
  GrVertex d = sdk_vertex(0, y1, w1, 200 - 140 * t1, 120 + 80 * t1, 60 + 30 * t1, 255);
  grDrawTriangle(&a, &b, &c);
  grDrawTriangle(&a, &c, &d);
}

int main(int argc, char **argv) {
  GrFog_t table[GR_FOG_TABLE_SIZE];
  int frame, frames, i;
  if (!sdk_open("fog_ramp", argc, argv, &frames)) return 1;
  guFogGenerateExp(table, 0.2f);
  grFogTable(table);
  grFogColorValue(0x00C09070); /* ABGR: r 0x70, g 0x90, b 0xC0 */
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  for (frame = 0; frame < frames; ++frame) {
    grBufferClear(0x00000000, 0, GR_WDEPTHVALUE_FARTHEST);
    /* The floor, far (w = 200) at the top, near (w = 1) at the bottom, in 16 bands. */
    grFogMode(GR_FOG_WITH_TABLE);
    for (i = 0; i < 16; ++i) floor_strip((float)i / 16.0f, (float)(i + 1) / 16.0f);
    grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
    /* Iterated-alpha fog: a bar from alpha 0 (left) to 255 (right). */
    grFogMode(GR_FOG_WITH_ITERATED_ALPHA);
    {
      GrVertex a = sdk_vertex(10, 170, 1, 250, 250, 250, 0), b = sdk_vertex(310, 170, 1, 250, 250, 250, 255);
      GrVertex c = sdk_vertex(310, 195, 1, 250, 250, 250, 255), d = sdk_vertex(10, 195, 1, 250, 250, 250, 0);
      grDrawTriangle(&a, &b, &c);
      grDrawTriangle(&a, &c, &d);
    }
    /* Iterated-Z fog: ooz from 0 to 65535, upper half plain, lower half MULT2. */
    for (i = 0; i < 2; ++i) {
      GrVertex a = sdk_vertex(10, 205.0f + 15.0f * (float)i, 1, 40, 40, 250, 255);
      GrVertex b = sdk_vertex(310, 205.0f + 15.0f * (float)i, 1, 40, 40, 250, 255);
      GrVertex c = sdk_vertex(310, 220.0f + 15.0f * (float)i, 1, 40, 40, 250, 255);
      GrVertex d = sdk_vertex(10, 220.0f + 15.0f * (float)i, 1, 40, 40, 250, 255);
      a.ooz = d.ooz = 0.0f;
      b.ooz = c.ooz = 65535.0f;
      grFogMode(GR_FOG_WITH_ITERATED_Z | (i == 1 ? GR_FOG_MULT2 : 0));
      grDrawTriangle(&a, &b, &c);
      grDrawTriangle(&a, &c, &d);
    }
    grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
    grBufferSwap(1);
  }
  return sdk_close();
}
