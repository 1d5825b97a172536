// guDrawTriangleWithClip, guDrawPolygonVertexListWithClip and guAADrawTriangleWithClip, as
// 3dfx's guclip.c does them: polygons inside the clip window go straight to the rasteriser; the
// rest are clipped in screen space (right, bottom, left, top), every attribute interpolated
// linearly, and drawn as a fan. There is no near-plane clipping: the program must keep w > 0,
// as on the hardware.
#include "draw.h"

#include <string>
#include <utility>
#include <vector>

namespace glide_shim {
namespace {

// Vertices this far out are still clipped in float (guclip.c does the same); beyond it, float
// precision in the interpolation is gone and the call is refused.
constexpr float kMaxClippedCoordinate = 1.0e7f;
static_assert(kMaxClippedCoordinate * 16.0f < 2147483648.0f,
              "to_shim_vertex snaps a checked coordinate through a 32-bit integer (draw.cpp)");

ShimVertex lerp(const ShimVertex &a, const ShimVertex &b, float t) {
  auto mix = [t](float u, float v) { return u + (v - u) * t; };
  return {mix(a.x, b.x),     mix(a.y, b.y), mix(a.depth, b.depth), mix(a.r, b.r),
          mix(a.g, b.g),     mix(a.b, b.b), mix(a.a, b.a),         mix(a.sow, b.sow),
          mix(a.tow, b.tow), mix(a.q, b.q), mix(a.fog, b.fog)};
}

// Keeps in `out` the part of `polygon` where sign * (coordinate - bound) >= 0.
void clip_edge(const std::vector<ShimVertex> &polygon, bool use_x, float bound, float sign,
               std::vector<ShimVertex> &out) {
  out.clear();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const ShimVertex &p = polygon[i];
    const ShimVertex &q = polygon[(i + 1) % n];
    const float dp = sign * ((use_x ? p.x : p.y) - bound);
    const float dq = sign * ((use_x ? q.x : q.y) - bound);
    if (dp >= 0.0f) out.push_back(p);
    if ((dp >= 0.0f) != (dq >= 0.0f)) out.push_back(lerp(p, q, dp / (dp - dq)));
  }
}

// Whether every vertex (screen pixels) lies inside the clip window.
bool inside_clip_window(const GlideContext &ctx, const ShimVertex *vertices, std::size_t count) {
  const auto &clip = ctx.raster.clip;
  const float min_x = static_cast<float>(clip.min_x), max_x = static_cast<float>(clip.max_x);
  const float min_y = static_cast<float>(clip.min_y), max_y = static_cast<float>(clip.max_y);
  bool inside = true;
  for (std::size_t i = 0; i < count; ++i) {
    const ShimVertex &v = vertices[i];
    inside = inside && v.x >= min_x && v.x < max_x && v.y >= min_y && v.y < max_y;
  }
  return inside;
}

// Clips a convex polygon (screen pixels) to the clip window unless it lies inside, then
// draws it as a fan from its first vertex; returns the polygon drawn.
std::vector<ShimVertex> clip_and_draw_fan(GlideContext &ctx, std::vector<ShimVertex> polygon) {
  if (!inside_clip_window(ctx, polygon.data(), polygon.size())) {
    const auto &clip = ctx.raster.clip;
    std::vector<ShimVertex> clipped;
    clip_edge(polygon, true, static_cast<float>(clip.max_x), -1.0f, clipped);
    clip_edge(clipped, false, static_cast<float>(clip.max_y), -1.0f, polygon);
    clip_edge(polygon, true, static_cast<float>(clip.min_x), 1.0f, clipped);
    clip_edge(clipped, false, static_cast<float>(clip.min_y), 1.0f, polygon);
    for (ShimVertex &v : polygon) v.x = snap(v.x), v.y = snap(v.y);
  }
  for (std::size_t i = 2; i < polygon.size(); ++i) {
    queue_triangle(ctx, polygon[0], polygon[i - 1], polygon[i]);
  }
  return polygon;
}

}  // namespace
}  // namespace glide_shim

using glide_shim::current;
using glide_shim::ShimVertex;

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void guDrawTriangleWithClip(const GrVertex *a, const GrVertex *b, const GrVertex *c) {
  auto &ctx = current();
  if (!ctx.require_open("guDrawTriangleWithClip")) return;
  if (a == nullptr || b == nullptr || c == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "guDrawTriangleWithClip: a vertex pointer is NULL");
    return;
  }
  // grDrawTriangle's cached fields and whole-triangle conversion (the same vertices as
  // to_shim_vertex's) for a triangle within the setup range; vertex by vertex, up to
  // kMaxClippedCoordinate and with the reports, otherwise.
  const glide_shim::VertexFields fields = glide_shim::current_vertex_fields(ctx);
  ShimVertex triangle[3];
  if (glide_shim::triangle_is_valid(fields, *a, *b, *c)) {
    glide_shim::convert_triangle(fields, *a, *b, *c, triangle);
  } else {
    const GrVertex *in[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
      if (!glide_shim::to_shim_vertex(ctx, fields, *in[i], triangle[i], "guDrawTriangleWithClip",
                                      glide_shim::kMaxClippedCoordinate)) {
        return;
      }
    }
  }
  // Inside the window (most triangles): what clip_and_draw_fan would queue, without its vector.
  if (glide_shim::inside_clip_window(ctx, triangle, 3)) {
    glide_shim::queue_triangle(ctx, triangle[0], triangle[1], triangle[2]);
    return;
  }
  glide_shim::clip_and_draw_fan(ctx, std::vector<ShimVertex>(triangle, triangle + 3));
}

void guDrawPolygonVertexListWithClip(int nverts, const GrVertex vlist[]) {
  auto &ctx = current();
  if (!ctx.require_open("guDrawPolygonVertexListWithClip")) return;
  if (vlist == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "guDrawPolygonVertexListWithClip: vlist is NULL");
    return;
  }
  if (!glide_shim::check_polygon_count(ctx, "guDrawPolygonVertexListWithClip", nverts)) return;
  const glide_shim::VertexFields fields = glide_shim::fields_read(ctx);
  std::vector<ShimVertex> polygon(static_cast<std::size_t>(nverts));
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    if (!glide_shim::to_shim_vertex(ctx, fields, vlist[i], polygon[i],
                                    "guDrawPolygonVertexListWithClip",
                                    glide_shim::kMaxClippedCoordinate)) {
      return;
    }
  }
  glide_shim::clip_and_draw_fan(ctx, std::move(polygon));
}

void guAADrawTriangleWithClip(const GrVertex *a, const GrVertex *b, const GrVertex *c) {
  auto &ctx = current();
  if (!ctx.require_open("guAADrawTriangleWithClip")) return;
  if (a == nullptr || b == nullptr || c == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "guAADrawTriangleWithClip: a vertex pointer is NULL");
    return;
  }
  const glide_shim::VertexFields fields = glide_shim::fields_read(ctx);
  std::vector<ShimVertex> polygon(3);
  const GrVertex *in[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    if (!glide_shim::to_shim_vertex(ctx, fields, *in[i], polygon[static_cast<std::size_t>(i)],
                                    "guAADrawTriangleWithClip", glide_shim::kMaxClippedCoordinate)) {
      return;
    }
  }
  // The clipped polygon with a fringe on every edge; fringes along the clip window's edges
  // fall outside it and are clipped away, as on the hardware.
  const std::vector<ShimVertex> drawn = glide_shim::clip_and_draw_fan(ctx, std::move(polygon));
  const float area = glide_shim::signed_area(drawn);
  if (area == 0.0f) return;
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    glide_shim::queue_fringe(ctx, drawn[i], drawn[(i + 1) % drawn.size()], area > 0.0f ? 1.0f : -1.0f);
  }
}

}  // namespace glide_shim_api
