/* polygon_fans: the polygon calls side by side. Top row: a Gouraud octagon through
 * grDrawPolygonVertexList, the same octagon indexed through grDrawPolygon (vertices stored
 * backwards), and a flat hexagon through grDrawPlanarPolygonVertexList. Bottom: a large star-
 * shaped fan (convex pieces) clipped by guDrawPolygonVertexListWithClip to a clip window,
 * whose outline is drawn with lines. */
#include "sdk_common.h"

#include <math.h>

static void regular(GrVertex *v, int n, float cx, float cy, float radius, float phase, int shade) {
  int i;
  for (i = 0; i < n; ++i) {
    const float angle = phase + 6.2831853f * (float)i / (float)n;
    v[i] = sdk_vertex(cx + radius * cosf(angle), cy + radius * sinf(angle), 1, 0, 0, 0, 255);
    v[i].r = shade ? 255.0f * (float)i / (float)n : 230;
    v[i].g = shade ? 255.0f - 255.0f * (float)i / (float)n : 200;
    v[i].b = shade ? 120 : 40;
  }
}

int main(int argc, char **argv) {
  GrVertex octagon[8], backwards[8], hexagon[6], piece[4];
  int ilist[8];
  int frame, frames, i;
  if (!sdk_open("polygon_fans", argc, argv, &frames)) return 1;
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  regular(octagon, 8, 55, 55, 45, 0.2f, 1);
  for (i = 0; i < 8; ++i) {
    backwards[i] = octagon[7 - i];
    ilist[i] = 7 - i;
  }
  regular(hexagon, 6, 265, 55, 45, 0.0f, 0);
  for (frame = 0; frame < frames; ++frame) {
    grClipWindow(0, 0, 320, 240);
    grBufferClear(0x00302020, 0, 0);
    grDrawPolygonVertexList(8, octagon);
    for (i = 0; i < 8; ++i) backwards[i].x += 105;
    grDrawPolygon(8, ilist, backwards);
    for (i = 0; i < 8; ++i) backwards[i].x -= 105;
    grDrawPlanarPolygonVertexList(6, hexagon);
    /* The clip window, outlined, then eight quadrilateral fans around a centre, clipped. */
    {
      GrVertex c0 = sdk_vertex(60, 120, 1, 255, 255, 255, 255), c1 = sdk_vertex(260, 120, 1, 255, 255, 255, 255);
      GrVertex c2 = sdk_vertex(260, 230, 1, 255, 255, 255, 255), c3 = sdk_vertex(60, 230, 1, 255, 255, 255, 255);
      grDrawLine(&c0, &c1);
      grDrawLine(&c1, &c2);
      grDrawLine(&c2, &c3);
      grDrawLine(&c3, &c0);
    }
    grClipWindow(61, 121, 260, 230);
    for (i = 0; i < 8; ++i) {
      const float a0 = 6.2831853f * (float)i / 8.0f, a1 = 6.2831853f * (float)(i + 1) / 8.0f;
      piece[0] = sdk_vertex(160, 175, 1, 250, 250, 250, 255);
      piece[1] = sdk_vertex(160 + 140 * cosf(a0), 175 + 140 * sinf(a0), 1, 250, 60, 60, 255);
      piece[2] = sdk_vertex(160 + 90 * cosf(0.5f * (a0 + a1)), 175 + 90 * sinf(0.5f * (a0 + a1)), 1, 60, 60, 250, 255);
      piece[3] = sdk_vertex(160 + 140 * cosf(a1), 175 + 140 * sinf(a1), 1, 60, 250, 60, 255);
      guDrawPolygonVertexListWithClip(4, piece);
    }
    grBufferSwap(1);
  }
  return sdk_close();
}
