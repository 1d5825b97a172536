// Chapter "drawing primitives": points, lines and triangles, and the cull mode.
#include "draw.h"

#include "depth.h"
#include "shader_source.h"

#include <cmath>
#include <string>

namespace glide_shim {
namespace {

// Programs that snap with the 3<<18 float trick sometimes never subtract it; the hardware
// keeps only the low bits, so neither does the shim (as OpenGLide does).
constexpr float kSnapOffset = 786432.0f;

float remove_snap_offset(float v) {
  return (v >= kSnapOffset - 4096.0f && v < kSnapOffset + 4096.0f) ? v - kSnapOffset : v;
}

}  // namespace

float snap(float coordinate) { return std::round(coordinate * 16.0f) / 16.0f; }

VertexFields fields_read(const GlideContext &context) {
  const CombineUnit &color = context.color_path.color;
  const CombineUnit &alpha = context.color_path.alpha;
  VertexFields fields{};
  fields.rgb = color.local == GR_COMBINE_LOCAL_ITERATED || color.other == GR_COMBINE_OTHER_ITERATED;
  fields.alpha = alpha.local == GR_COMBINE_LOCAL_ITERATED || alpha.other == GR_COMBINE_OTHER_ITERATED;
  fields.texture = reads_texture(context.color_path);
  fields.ooz = context.depth.mode == GR_DEPTHBUFFER_ZBUFFER;
  fields.oow = is_w_buffer(context.depth.mode) || fields.texture;
  return fields;
}

bool to_shim_vertex(GlideContext &context, const VertexFields &fields, const GrVertex &in,
                    ShimVertex &out, const char *function, float max_coordinate) {
  out = ShimVertex{};
  const float x = remove_snap_offset(in.x), y = remove_snap_offset(in.y);
  bool finite = std::isfinite(x) && std::isfinite(y);
  if (fields.rgb) finite = finite && std::isfinite(in.r) && std::isfinite(in.g) && std::isfinite(in.b);
  if (fields.alpha) finite = finite && std::isfinite(in.a);
  if (fields.ooz) finite = finite && std::isfinite(in.ooz);
  if (fields.oow) finite = finite && std::isfinite(in.oow);
  if (fields.texture) {
    finite = finite && std::isfinite(in.tmuvtx[0].sow) && std::isfinite(in.tmuvtx[0].tow) &&
             std::isfinite(in.tmuvtx[0].oow);
  }
  if (!finite) {
    context.report(GLIDESHIM_ERR_INVALID_VALUE,
                   std::string(function) + ": a vertex field the current state reads is NaN or infinite");
    return false;
  }
  if (std::fabs(x) > max_coordinate || std::fabs(y) > max_coordinate) {
    context.report(GLIDESHIM_ERR_INVALID_VALUE,
                   std::string(function) + ": vertex (" + std::to_string(x) + ", " +
                       std::to_string(y) + ") is beyond +-" + std::to_string(max_coordinate));
    return false;
  }
  out.x = snap(x);
  out.y = snap(y);
  if (fields.rgb) out.r = in.r, out.g = in.g, out.b = in.b;
  if (fields.alpha) out.a = in.a;
  out.depth = vertex_depth(context.depth, fields.ooz ? in.ooz : 0.0f, fields.oow ? in.oow : 0.0f);
  if (fields.texture) {
    out.sow = in.tmuvtx[0].sow;
    out.tow = in.tmuvtx[0].tow;
    // GR_STWHINT_W_DIFF_TMU0: TMU0 divides by its own w (the projective-texture path).
    out.q = (context.raster.stw_hint & GR_STWHINT_W_DIFF_TMU0) != 0 ? in.tmuvtx[0].oow : in.oow;
  }
  return true;
}

void queue_triangle(GlideContext &context, const ShimVertex &a, const ShimVertex &b,
                    const ShimVertex &c) {
  const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  if (area == 0.0f) return;
  if (context.raster.cull == GR_CULL_NEGATIVE && area < 0.0f) return;
  if (context.raster.cull == GR_CULL_POSITIVE && area > 0.0f) return;
  const ShimVertex triangle[3] = {a, b, c};
  context.renderer->queue(Primitive::Triangles, triangle, 3);
}

}  // namespace glide_shim

using glide_shim::current;

extern "C" {

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
  const glide_shim::VertexFields fields = glide_shim::fields_read(ctx);
  glide_shim::ShimVertex v[3];
  if (!glide_shim::to_shim_vertex(ctx, fields, *a, v[0], "grDrawTriangle") ||
      !glide_shim::to_shim_vertex(ctx, fields, *b, v[1], "grDrawTriangle") ||
      !glide_shim::to_shim_vertex(ctx, fields, *c, v[2], "grDrawTriangle")) {
    return;
  }
  glide_shim::queue_triangle(ctx, v[0], v[1], v[2]);
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

}  // extern "C"
