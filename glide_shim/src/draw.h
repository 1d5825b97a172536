// From the program's GrVertex to the shim's vertex: only the fields the current state reads are
// taken (programs leave the rest uninitialised), checked, and snapped to the 12.4 grid.
#pragma once

#include "context.h"
#include "gl/gl_renderer.h"
#include "vertex_fields.h"

#include <vector>

namespace glide_shim {

VertexFields fields_read(const GlideContext &context);

// The largest |x| or |y| the rasteriser takes: Glide's 12.4 fixed-point setup range.
constexpr float kMaxScreenCoordinate = 32768.0f;

// Programs that snap with the 3<<18 float trick sometimes never subtract it; the hardware
// keeps only the low bits, so neither does the shim (as OpenGLide does): a coordinate within
// 4096 of this offset is taken less it.
constexpr float kSnapOffset = 786432.0f;

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

// fields_read(context), recomputed only when a flush has marked the context's copy stale.
const VertexFields &current_vertex_fields(GlideContext &context);
// check_vertex and write_vertex for a triangle at once, with the same results: true when all
// three vertices pass the checks (none reported: check_vertex tells which failed), and the
// three converted vertices.
bool triangle_is_valid(const VertexFields &fields, const GrVertex &a, const GrVertex &b,
                       const GrVertex &c);
void convert_triangle(const VertexFields &fields, const GrVertex &a, const GrVertex &b,
                      const GrVertex &c, ShimVertex *out);
// Both at once: the three converted vertices queued as a triangle when the checks pass, else
// null with nothing queued or reported.
ShimVertex *queue_checked_triangle(GlRenderer &renderer, const VertexFields &fields,
                                   const GrVertex &a, const GrVertex &b, const GrVertex &c);

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
