// Chapter "drawing primitives": points, lines, triangles and polygons (fans), their antialiased
// forms (alpha fringes along the edges, as gaa.c draws them), and the cull mode.
#include "draw.h"

#include "depth.h"
#include "gl/shader_source.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace glide_shim {
namespace {

float remove_snap_offset(float v) {
  return (v >= kSnapOffset - 4096.0f && v < kSnapOffset + 4096.0f) ? v - kSnapOffset : v;
}

}  // namespace

namespace {

// snap for the coordinates the checks let through (|coordinate| <= 1e7, so |16 coordinate| <
// 2^31): std::round(coordinate * 16) / 16 without the libm call the baseline x86-64 target
// makes of it. The product is exact, its truncation toward zero and the fraction left are
// exact, and a fraction of at least one half steps away from zero as std::round does; copysign
// keeps a negative zero negative.
inline float snap_checked(float coordinate) {
  const float scaled = coordinate * 16.0f;
  const std::int32_t whole = static_cast<std::int32_t>(scaled);
  const float fraction = scaled - static_cast<float>(whole);
  const std::int32_t rounded = whole + (fraction >= 0.5f ? 1 : 0) - (fraction <= -0.5f ? 1 : 0);
  return std::copysign(static_cast<float>(rounded) * 0.0625f, scaled);
}

}  // namespace

float snap(float coordinate) {
  if (!(std::fabs(coordinate) < 1.0e8f)) return std::round(coordinate * 16.0f) / 16.0f;
  return snap_checked(coordinate);
}

VertexFields fields_read(const GlideContext &context) {
  const ColorPathState &path = context.color_path;
  const CombineUnit &color = path.color;
  const CombineUnit &alpha = path.alpha;
  const GrDepthBufferMode_t depth_mode = context.depth.mode;
  VertexFields fields{};
  // In delta0 mode the driver sends no vertex colour: the iterators hold grConstantColorValue4's.
  fields.delta0 = path.delta0;
  fields.rgb = !path.delta0 &&
               (color.local == GR_COMBINE_LOCAL_ITERATED || color.other == GR_COMBINE_OTHER_ITERATED ||
                path.alpha_controls_itrgb);
  if (path.delta0) {
    // Fr/Fg/Fb hold the colour in 12.12 with zero slopes; the pixel sees its integer part.
    for (int i = 0; i < 3; ++i) fields.delta0_rgb[i] = std::floor(path.iterated4[i + 1]);
  }
  fields.alpha = alpha.local == GR_COMBINE_LOCAL_ITERATED || alpha.other == GR_COMBINE_OTHER_ITERATED;
  fields.texture = reads_texture(path);
  fields.fog = context.fog.mode & 0xFF;
  fields.alpha = fields.alpha || fields.fog == GR_FOG_WITH_ITERATED_ALPHA;
  fields.ooz = is_z_buffer(depth_mode) || fields.fog == GR_FOG_WITH_ITERATED_Z;
  fields.oow = is_w_buffer(depth_mode) || fields.texture || fields.fog == GR_FOG_WITH_TABLE;
  // GR_STWHINT_W_DIFF_TMU0: TMU0 divides by its own w (the projective-texture path).
  fields.q_from_tmu = (context.raster.stw_hint & GR_STWHINT_W_DIFF_TMU0) != 0;
  fields.depth = &context.depth;
  const bool unbiased = compares_to_bias(depth_mode) || context.depth.bias_level == 0;
  fields.depth_source = depth_mode == GR_DEPTHBUFFER_DISABLE            ? DepthSource::None
                        : is_w_buffer(depth_mode) && unbiased ? DepthSource::UnbiasedW
                                                                        : DepthSource::General;
  // The floats vertex_is_valid probes, by their index in GrVertex (see kCheckedVertexFloats).
  const bool checked[kCheckedVertexFloats] = {true,          true,         false,        fields.rgb,
                                              fields.rgb,    fields.rgb,   fields.ooz,   fields.alpha,
                                              fields.oow,    fields.texture, fields.texture,
                                              fields.texture};
  for (int i = 0; i < kCheckedVertexFloats; ++i) {
    fields.checked_exponents[i] = checked[i] ? 0x7F800000u : 0u;
  }
  return fields;
}

namespace {

// The reports of check_vertex, out of its way: the checks themselves are a few instructions.
[[gnu::cold, gnu::noinline]] void report_bad_vertex(GlideContext &context, const char *function,
                                                     bool finite, float x, float y,
                                                     float max_coordinate) {
  if (!finite) {
    context.report(GLIDESHIM_ERR_INVALID_VALUE,
                   std::string(function) + ": a vertex field the current state reads is NaN or infinite");
    return;
  }
  context.report(GLIDESHIM_ERR_INVALID_VALUE,
                 std::string(function) + ": vertex (" + std::to_string(x) + ", " +
                     std::to_string(y) + ") is beyond +-" + std::to_string(max_coordinate));
}

inline bool vertex_is_valid(GlideContext &context, const VertexFields &fields, const GrVertex &in,
                            const char *function, float max_coordinate) {
  const float x = remove_snap_offset(in.x), y = remove_snap_offset(in.y);
  // v * 0 is NaN exactly when v is NaN or infinite, and a NaN survives the sum: one test for
  // every field the current state reads.
  float probe = x * 0.0f + y * 0.0f;
  if (fields.rgb) probe += in.r * 0.0f + in.g * 0.0f + in.b * 0.0f;
  if (fields.alpha) probe += in.a * 0.0f;
  if (fields.ooz) probe += in.ooz * 0.0f;
  if (fields.oow) probe += in.oow * 0.0f;
  if (fields.texture) {
    probe += in.tmuvtx[0].sow * 0.0f + in.tmuvtx[0].tow * 0.0f + in.tmuvtx[0].oow * 0.0f;
  }
  const bool finite = !std::isnan(probe);
  if (finite && std::fabs(x) <= max_coordinate && std::fabs(y) <= max_coordinate) return true;
  report_bad_vertex(context, function, finite, x, y, max_coordinate);
  return false;
}

inline void convert_vertex(const VertexFields &fields, const GrVertex &in, ShimVertex &out) {
  out.x = snap_checked(remove_snap_offset(in.x));  // checked: |x|, |y| <= 1e7
  out.y = snap_checked(remove_snap_offset(in.y));
  switch (fields.depth_source) {
    case DepthSource::None: out.depth = 0.0f; break;
    case DepthSource::UnbiasedW: out.depth = std::clamp(std::min(in.oow, 1.0f), 0.0f, 1.0f); break;
    default:
      out.depth = vertex_depth(*fields.depth, fields.ooz ? in.ooz : 0.0f, fields.oow ? in.oow : 0.0f);
  }
  if (fields.delta0) {
    out.r = fields.delta0_rgb[0], out.g = fields.delta0_rgb[1], out.b = fields.delta0_rgb[2];
  } else if (fields.rgb) {
    out.r = in.r, out.g = in.g, out.b = in.b;
  } else {
    out.r = out.g = out.b = 0.0f;
  }
  out.a = fields.alpha ? in.a : 0.0f;
  out.fog = fields.fog == GR_FOG_WITH_TABLE ? in.oow : fields.fog == GR_FOG_WITH_ITERATED_Z ? in.ooz : 0.0f;
  if (fields.texture) {
    out.sow = in.tmuvtx[0].sow;
    out.tow = in.tmuvtx[0].tow;
    out.q = fields.q_from_tmu ? in.tmuvtx[0].oow : in.oow;
  } else {
    out.sow = out.tow = out.q = 0.0f;
  }
}

}  // namespace

bool check_vertex(GlideContext &context, const VertexFields &fields, const GrVertex &in,
                  const char *function, float max_coordinate) {
  return vertex_is_valid(context, fields, in, function, max_coordinate);
}

void write_vertex(const VertexFields &fields, const GrVertex &in, ShimVertex &out) {
  convert_vertex(fields, in, out);
}

bool to_shim_vertex(GlideContext &context, const VertexFields &fields, const GrVertex &in,
                    ShimVertex &out, const char *function, float max_coordinate) {
  if (!check_vertex(context, fields, in, function, max_coordinate)) return false;
  write_vertex(fields, in, out);
  return true;
}

bool keeps_triangle(GlideContext &context, const ShimVertex &a, const ShimVertex &b,
                    const ShimVertex &c) {
  const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  ++context.perf.triangles_processed;
  if (area == 0.0f) return false;
  if (context.raster.cull == GR_CULL_NEGATIVE && area < 0.0f) return false;
  if (context.raster.cull == GR_CULL_POSITIVE && area > 0.0f) return false;
  ++context.perf.triangles_drawn;
  return true;
}

void queue_triangle(GlideContext &context, const ShimVertex &a, const ShimVertex &b,
                    const ShimVertex &c) {
  if (!keeps_triangle(context, a, b, c)) return;
  const ShimVertex triangle[3] = {a, b, c};
  context.renderer->queue(Primitive::Triangles, triangle, 3);
}

// Twice the signed area of a polygon in screen pixels (the sign is its winding).
float signed_area(const std::vector<ShimVertex> &polygon) {
  float area = 0.0f;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const ShimVertex &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    area += p.x * q.y - q.x * p.y;
  }
  return area;
}

// The hardware's antialiasing (gaa.c): a one-pixel fringe outside edge p->q, stepped along the
// edge's minor axis, whose outer vertices have alpha 0, so blending with the iterated alpha
// fades the edge. Wound like the polygon, so culling treats it the same.
void queue_fringe(GlideContext &context, const ShimVertex &p, const ShimVertex &q, float winding) {
  const float dx = q.x - p.x, dy = q.y - p.y;
  const float out_x = winding * dy, out_y = -winding * dx;  // outward normal (screen pixels)
  ShimVertex p_out = p, q_out = q;
  if (std::fabs(dx) >= std::fabs(dy)) {
    const float step = out_y > 0.0f ? 1.0f : -1.0f;
    p_out.y += step, q_out.y += step;
  } else {
    const float step = out_x > 0.0f ? 1.0f : -1.0f;
    p_out.x += step, q_out.x += step;
  }
  p_out.a = q_out.a = 0.0f;
  queue_triangle(context, q, p, p_out);
  queue_triangle(context, q, p_out, q_out);
}

bool check_polygon_count(GlideContext &context, const char *function, int nverts) {
  if (nverts < 3) {
    context.report(GLIDESHIM_ERR_OUT_OF_RANGE, std::string(function) + ": " +
                                                   std::to_string(nverts) +
                                                   " vertices; a polygon needs at least 3");
    return false;
  }
  if (nverts > kMaxPolygonVertices) {
    context.report(GLIDESHIM_ERR_OUT_OF_RANGE,
                   std::string(function) + ": " + std::to_string(nverts) +
                       " vertices, more than the limit of " + std::to_string(kMaxPolygonVertices));
    return false;
  }
  return true;
}

namespace {

// The program's polygon (through `ilist` when given) as shim vertices; false after reporting.
bool convert_polygon(GlideContext &context, const char *function, int nverts, const int *ilist,
                     bool indexed, const GrVertex *vlist, std::vector<ShimVertex> &out) {
  if (vlist == nullptr || (indexed && ilist == nullptr)) {
    context.report(GLIDESHIM_ERR_NULL_POINTER,
                   std::string(function) + (vlist == nullptr ? ": vlist is NULL" : ": ilist is NULL"));
    return false;
  }
  if (!check_polygon_count(context, function, nverts)) return false;
  const VertexFields fields = fields_read(context);
  std::vector<ShimVertex> polygon(static_cast<std::size_t>(nverts));
  for (int i = 0; i < nverts; ++i) {
    const int index = indexed ? ilist[i] : i;
    if (index < 0) {
      context.report(GLIDESHIM_ERR_OUT_OF_RANGE, std::string(function) + ": ilist[" +
                                                     std::to_string(i) + "] is negative");
      return false;
    }
    if (!to_shim_vertex(context, fields, vlist[index], polygon[static_cast<std::size_t>(i)], function)) {
      return false;
    }
  }
  out = std::move(polygon);
  return true;
}

// A fan from the first vertex, as gdraw.c draws polygons; planar polygons come out the same,
// since their attributes are planar by contract.
void queue_fan(GlideContext &context, const std::vector<ShimVertex> &polygon) {
  for (std::size_t i = 2; i < polygon.size(); ++i) {
    queue_triangle(context, polygon[0], polygon[i - 1], polygon[i]);
  }
}

void draw_polygon(const char *function, int nverts, const int *ilist, bool indexed,
                  const GrVertex *vlist, bool antialiased) {
  auto &ctx = current();
  if (!ctx.require_open(function)) return;
  std::vector<ShimVertex> polygon;
  if (!convert_polygon(ctx, function, nverts, ilist, indexed, vlist, polygon)) return;
  queue_fan(ctx, polygon);
  const float area = signed_area(polygon);
  if (!antialiased || area == 0.0f) return;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    queue_fringe(ctx, polygon[i], polygon[(i + 1) % polygon.size()], area > 0.0f ? 1.0f : -1.0f);
  }
}

}  // namespace
}  // namespace glide_shim

using glide_shim::current;

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grCullMode(GrCullMode_t mode) {
  auto &ctx = current();
  if (!ctx.require_open("grCullMode")) return;
  if (mode != GR_CULL_DISABLE && mode != GR_CULL_NEGATIVE && mode != GR_CULL_POSITIVE) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grCullMode: unknown mode " + std::to_string(mode));
    return;
  }
  ctx.raster.cull = mode;  // applied on the CPU as triangles arrive: no flush needed
}

void grDrawTriangle(const GrVertex *a, const GrVertex *b, const GrVertex *c) {
  auto &ctx = current();
  if (!ctx.require_open("grDrawTriangle")) return;
  if (a == nullptr || b == nullptr || c == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grDrawTriangle: a vertex pointer is NULL");
    return;
  }
  const glide_shim::VertexFields &fields = glide_shim::current_vertex_fields(ctx);
  // Checked before the queue grows (an error callback may flush): the vertices go straight in.
  glide_shim::ShimVertex *v = glide_shim::queue_checked_triangle(*ctx.renderer, fields, *a, *b, *c);
  if (v == nullptr) {
    // The same checks vertex by vertex find the first bad vertex and report it.
    for (const GrVertex *vertex : {a, b, c}) {
      if (!glide_shim::check_vertex(ctx, fields, *vertex, "grDrawTriangle")) return;
    }
    return;
  }
  if (!glide_shim::keeps_triangle(ctx, v[0], v[1], v[2])) ctx.renderer->unqueue(3);
}

void grDrawLine(const GrVertex *v1, const GrVertex *v2) {
  auto &ctx = current();
  if (!ctx.require_open("grDrawLine")) return;
  if (v1 == nullptr || v2 == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grDrawLine: a vertex pointer is NULL");
    return;
  }
  const glide_shim::VertexFields fields = glide_shim::fields_read(ctx);
  glide_shim::ShimVertex v[2];
  if (!glide_shim::to_shim_vertex(ctx, fields, *v1, v[0], "grDrawLine") ||
      !glide_shim::to_shim_vertex(ctx, fields, *v2, v[1], "grDrawLine")) {
    return;
  }
  ctx.renderer->queue(glide_shim::Primitive::Lines, v, 2);
}

void grDrawPoint(const GrVertex *pt) {
  auto &ctx = current();
  if (!ctx.require_open("grDrawPoint")) return;
  if (pt == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grDrawPoint: pt is NULL");
    return;
  }
  glide_shim::ShimVertex v;
  if (!glide_shim::to_shim_vertex(ctx, glide_shim::fields_read(ctx), *pt, v, "grDrawPoint")) return;
  // The hardware truncates a point to its pixel and draws that pixel's centre.
  v.x = std::floor(v.x) + 0.5f;
  v.y = std::floor(v.y) + 0.5f;
  ctx.renderer->queue(glide_shim::Primitive::Points, &v, 1);
}

void grDrawPolygon(int nverts, const int ilist[], const GrVertex vlist[]) {
  glide_shim::draw_polygon("grDrawPolygon", nverts, ilist, true, vlist, false);
}

void grDrawPlanarPolygon(int nverts, const int ilist[], const GrVertex vlist[]) {
  glide_shim::draw_polygon("grDrawPlanarPolygon", nverts, ilist, true, vlist, false);
}

void grDrawPolygonVertexList(int nverts, const GrVertex vlist[]) {
  glide_shim::draw_polygon("grDrawPolygonVertexList", nverts, nullptr, false, vlist, false);
}

void grDrawPlanarPolygonVertexList(int nverts, const GrVertex vlist[]) {
  glide_shim::draw_polygon("grDrawPlanarPolygonVertexList", nverts, nullptr, false, vlist, false);
}

void grAADrawPolygon(const int nverts, const int ilist[], const GrVertex vlist[]) {
  glide_shim::draw_polygon("grAADrawPolygon", nverts, ilist, true, vlist, true);
}

void grAADrawPolygonVertexList(const int nverts, const GrVertex vlist[]) {
  glide_shim::draw_polygon("grAADrawPolygonVertexList", nverts, nullptr, false, vlist, true);
}

void grAADrawTriangle(const GrVertex *a, const GrVertex *b, const GrVertex *c, FxBool ab_antialias,
                      FxBool bc_antialias, FxBool ca_antialias) {
  auto &ctx = current();
  if (!ctx.require_open("grAADrawTriangle")) return;
  if (a == nullptr || b == nullptr || c == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grAADrawTriangle: a vertex pointer is NULL");
    return;
  }
  const GrVertex list[3] = {*a, *b, *c};
  std::vector<glide_shim::ShimVertex> v;
  if (!glide_shim::convert_polygon(ctx, "grAADrawTriangle", 3, nullptr, false, list, v)) return;
  glide_shim::queue_triangle(ctx, v[0], v[1], v[2]);
  const float area = glide_shim::signed_area(v);
  if (area == 0.0f) return;
  const float winding = area > 0.0f ? 1.0f : -1.0f;
  if (ab_antialias) glide_shim::queue_fringe(ctx, v[0], v[1], winding);
  if (bc_antialias) glide_shim::queue_fringe(ctx, v[1], v[2], winding);
  if (ca_antialias) glide_shim::queue_fringe(ctx, v[2], v[0], winding);
}

void grAADrawLine(const GrVertex *v1, const GrVertex *v2) {
  auto &ctx = current();
  if (!ctx.require_open("grAADrawLine")) return;
  if (v1 == nullptr || v2 == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grAADrawLine: a vertex pointer is NULL");
    return;
  }
  const glide_shim::VertexFields fields = glide_shim::fields_read(ctx);
  glide_shim::ShimVertex v[2];
  if (!glide_shim::to_shim_vertex(ctx, fields, *v1, v[0], "grAADrawLine") ||
      !glide_shim::to_shim_vertex(ctx, fields, *v2, v[1], "grAADrawLine")) {
    return;
  }
  // The line's core at full alpha, then a one-pixel fringe on either side along the minor axis
  // fading to alpha 0 (gaa.c's two-sided ramp).
  ctx.renderer->queue(glide_shim::Primitive::Lines, v, 2);
  glide_shim::queue_fringe(ctx, v[0], v[1], 1.0f);
  glide_shim::queue_fringe(ctx, v[0], v[1], -1.0f);
}

void grAADrawPoint(const GrVertex *pt) {
  auto &ctx = current();
  if (!ctx.require_open("grAADrawPoint")) return;
  if (pt == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grAADrawPoint: pt is NULL");
    return;
  }
  glide_shim_api::grDrawPoint(pt);  // drawn without a fringe: one pixel, like grDrawPoint
}

}  // namespace glide_shim_api
