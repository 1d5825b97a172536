/* aa_lines: antialiased lines and triangles blended over a dark background. Left: a fan of
 * grAADrawLine lines beside the same lines from grDrawLine. Right: a triangle from
 * grAADrawTriangle with all edges antialiased above one with none, and an antialiased
 * pentagon (grAADrawPolygonVertexList). Antialiasing needs the iterated alpha and blending. */
#include "sdk_common.h"

#include <math.h>

int main(int argc, char **argv) {
  int frame, frames, i;
  if (!sdk_open("aa_lines", argc, argv, &frames)) return 1;
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
  for (frame = 0; frame < frames; ++frame) {
    grBufferClear(0x00301008, 0, 0);
    for (i = 0; i < 12; ++i) {
      const float angle = 1.5707963f * (float)i / 11.0f;
      GrVertex a = sdk_vertex(10, 10, 1, 255, 255, 200, 255);
      GrVertex b = sdk_vertex(10 + 140 * cosf(angle), 10 + 100 * sinf(angle), 1, 255, 255, 200, 255);
      GrVertex c = a, d = b;
      grAADrawLine(&a, &b);
      c.y += 120, d.y += 120;
      grDrawLine(&c, &d);
    }
    {
      GrVertex a = sdk_vertex(180, 15, 1, 250, 90, 40, 255), b = sdk_vertex(300, 40, 1, 250, 200, 40, 255);
      GrVertex c = sdk_vertex(200, 105, 1, 250, 90, 200, 255);
      GrVertex pentagon[5];
      grAADrawTriangle(&a, &b, &c, FXTRUE, FXTRUE, FXTRUE);
      a.y += 100, b.y += 100, c.y += 100;
      grAADrawTriangle(&a, &b, &c, FXFALSE, FXFALSE, FXFALSE);
      for (i = 0; i < 5; ++i) {
        const float angle = 0.3f + 6.2831853f * (float)i / 5.0f;
        pentagon[i] = sdk_vertex(280 + 30 * cosf(angle), 190 + 30 * sinf(angle), 1, 90, 220, 250, 255);
      }
      grAADrawPolygonVertexList(5, pentagon);
    }
    grBufferSwap(1);
  }
  return sdk_close();
}
