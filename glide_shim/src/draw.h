// From the program's GrVertex to the shim's vertex: only the fields the current state reads are
// taken (programs leave the rest uninitialised), checked, and snapped to the 12.4 grid.
#pragma once

#include "context.h"
#include "gl/gl_renderer.h"

#include <vector>

namespace glide_shim {

// How a vertex's GL depth is formed: none (depth buffering off: 0), the W-buffer's 1/w with
// no bias (clamped to 0..1), or vertex_depth's general case (a Z-buffer, a biased W-buffer).
enum class DepthSource { None, UnbiasedW, General };

struct VertexFields {  // which GrVertex fields the current state reads, and how it reads them
  bool rgb, alpha, ooz, oow, texture;
  GrFogMode_t fog;  // the fog source: table fog reads oow, iterated-Z fog ooz, iterated alpha a
  bool delta0;      // the RGB iterators hold delta0_rgb (guColorCombineFunction's *_DELTA0)
  float delta0_rgb[3];
  bool q_from_tmu;  // GR_STWHINT_W_DIFF_TMU0: the texture divisor is tmuvtx[0].oow, not oow
  DepthSource depth_source;
  const DepthState *depth;  // the context's, for DepthSource::General
};

VertexFields fields_read(const GlideContext &context);

// The largest |x| or |y| the rasteriser takes: Glide's 12.4 fixed-point setup range.
constexpr float kMaxScreenCoordinate = 32768.0f;

// The most vertices a polygon call takes. Glide sets no maximum; a count beyond this is a
// corrupt argument, not a polygon, and would otherwise be allocated and read before any check.
constexpr int kMaxPolygonVertices = 65536;

// False (with an error reported naming `function`) for a polygon count outside 3..65536.
bool check_polygon_count(GlideContext &context, const char *function, int nverts);

// False (with an error reported naming `function`) for NaN, infinity or coordinates beyond
// `max_coordinate`; guDrawTriangleWithClip passes a larger bound, since it clips first.
bool to_shim_vertex(GlideContext &context, const VertexFields &fields, const GrVertex &in,
                    ShimVertex &out, const char *function,
                    float max_coordinate = kMaxScreenCoordinate);
// to_shim_vertex's two halves: the checks (reporting), then the conversion of a checked vertex.
bool check_vertex(GlideContext &context, const VertexFields &fields, const GrVertex &in,
                  const char *function, float max_coordinate = kMaxScreenCoordinate);
void write_vertex(const VertexFields &fields, const GrVertex &in, ShimVertex &out);

// False for a triangle that is not drawn: zero signed area of the snapped vertices, or culled.
// Counts it for grSstPerfStats.
bool keeps_triangle(GlideContext &context, const ShimVertex &a, const ShimVertex &b,
                    const ShimVertex &c);
// Culls by the signed area of the snapped vertices (zero area is always dropped) and queues.
void queue_triangle(GlideContext &context, const ShimVertex &a, const ShimVertex &b,
                    const ShimVertex &c);

float snap(float coordinate);  // to 1/16 pixel, as the hardware's 12.4 setup does

// Twice the signed area of a polygon in screen pixels; its sign is the winding.
float signed_area(const std::vector<ShimVertex> &polygon);
// The antialiasing fringe outside edge p->q of a polygon wound as `winding` (+1 or -1).
void queue_fringe(GlideContext &context, const ShimVertex &p, const ShimVertex &q, float winding);

}  // namespace glide_shim
