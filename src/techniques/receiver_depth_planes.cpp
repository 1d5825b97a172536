// Step 4's triangles as the shim rasterises them, and clipped receiver pieces cut along them
// with their depth on those triangles' planes (receiver_depth_planes.h). Spaces: Glide screen
// (pixels, y down); depth the W buffer's unbiased 1/w.
#include "techniques/receiver_depth_planes.h"

#include <algorithm>
#include <cmath>

namespace gs {
namespace {

// A corner as the shim holds it: x, y snapped, depth clamped, all float; its clip-window
// clipping interpolates them in float (glide_shim/src/clip.cpp), which this follows to the bit.
struct Corner {
  float x, y, depth;
};

// The shim's snap to 1/16 pixel (the hardware's 12.4 set-up): to nearest, halves away from zero.
float snap(float coordinate) { return std::round(coordinate * 16.0f) / 16.0f; }

Corner corner_of(const GrVertex &v) {
  return {snap(v.x), snap(v.y), std::clamp(std::min(v.oow, 1.0f), 0.0f, 1.0f)};
}

// The part of `polygon` where sign * (coordinate - bound) >= 0, as the shim's clip_edge.
void clip_window_edge(const std::vector<Corner> &polygon, bool use_x, float bound, float sign,
                      std::vector<Corner> &out) {
  out.clear();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Corner &p = polygon[i], &q = polygon[(i + 1) % n];
    const float dp = sign * ((use_x ? p.x : p.y) - bound);
    const float dq = sign * ((use_x ? q.x : q.y) - bound);
    if (dp >= 0.0f) out.push_back(p);
    if ((dp >= 0.0f) != (dq >= 0.0f)) {
      const float t = dp / (dp - dq);
      auto mix = [t](float u, float v) { return u + (v - u) * t; };
      out.push_back({mix(p.x, q.x), mix(p.y, q.y), mix(p.depth, q.depth)});
    }
  }
}

// guDrawTriangleWithClip of a, b, c under the scene's state (W buffer without bias, clockwise
// triangles kept: GR_CULL_POSITIVE) in a width x height clip window: the triangles it queues.
void add_drawn(const GrVertex &a, const GrVertex &b, const GrVertex &c, float width, float height,
               std::vector<DrawnTriangle> &out) {
  std::vector<Corner> polygon = {corner_of(a), corner_of(b), corner_of(c)}, scratch;
  const bool inside = std::all_of(polygon.begin(), polygon.end(), [&](const Corner &v) {
    return v.x >= 0.0f && v.x < width && v.y >= 0.0f && v.y < height;
  });
  if (!inside) {
    clip_window_edge(polygon, true, width, -1.0f, scratch);
    clip_window_edge(scratch, false, height, -1.0f, polygon);
    clip_window_edge(polygon, true, 0.0f, 1.0f, scratch);
    clip_window_edge(scratch, false, 0.0f, 1.0f, polygon);
    for (Corner &v : polygon) v.x = snap(v.x), v.y = snap(v.y);
  }
  for (std::size_t i = 2; i < polygon.size(); ++i) {
    const Corner &p = polygon[0], &q = polygon[i - 1], &r = polygon[i];
    const float area = (q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y);
    if (!(area < 0.0f)) continue;  // zero area, or culled
    out.push_back({{{p.x, p.y}, {q.x, q.y}, {r.x, r.y}}, {p.depth, q.depth, r.depth}});
  }
}

// A vertex during the cut: its screen position and the fields that follow it, in double.
struct CutVertex {
  glm::dvec2 p;
  double oow, a, sow, tow, q;  // q: tmuvtx[0].oow
};

bool before(const CutVertex &u, const CutVertex &v) {
  return u.p.x < v.p.x || (u.p.x == v.p.x && u.p.y < v.p.y);
}

double cross(const glm::dvec2 &u, const glm::dvec2 &v) { return u.x * v.y - u.y * v.x; }

// The line through a drawn triangle's edge, its ends in a fixed order whichever triangle it
// comes from, so that two triangles sharing the edge cut a segment at the very same point.
struct EdgeLine {
  glm::dvec2 low, high;
  double side;  // +1 or -1: the triangle's side of the line
  double value(const glm::dvec2 &q) const { return side * cross(high - low, q - low); }
};

EdgeLine edge_line(const glm::vec2 &u, const glm::vec2 &v, const glm::vec2 &opposite) {
  EdgeLine line;
  const bool u_first = u.x < v.x || (u.x == v.x && u.y < v.y);
  line.low = glm::dvec2(u_first ? u : v), line.high = glm::dvec2(u_first ? v : u);
  line.side = 1.0;
  line.side = line.value(glm::dvec2(opposite)) < 0.0 ? -1.0 : 1.0;
  return line;
}

// Keeps the part of `polygon` on the triangle's side of `line` (on it included). A segment is
// cut at the point found from its ends in a fixed order, the same from either side.
void cut(std::vector<CutVertex> &polygon, const EdgeLine &line, std::vector<CutVertex> &scratch) {
  scratch.clear();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const CutVertex &p = polygon[i], &q = polygon[(i + 1) % n];
    const double dp = line.value(p.p), dq = line.value(q.p);
    if (dp >= 0.0) scratch.push_back(p);
    if ((dp > 0.0 && dq < 0.0) || (dp < 0.0 && dq > 0.0)) {
      const CutVertex &u = before(p, q) ? p : q, &v = before(p, q) ? q : p;
      const double du = line.value(u.p), dv = line.value(v.p);
      const double t = du / (du - dv);
      auto mix = [t](double a, double b) { return a + (b - a) * t; };
      scratch.push_back({u.p + (v.p - u.p) * t, mix(u.oow, v.oow), mix(u.a, v.a),
                         mix(u.sow, v.sow), mix(u.tow, v.tow), mix(u.q, v.q)});
    }
  }
  polygon.swap(scratch);
}

// The unbiased W depth of `drawn`'s plane at the screen point q (its snapped position).
double depth_at(const DrawnTriangle &drawn, const glm::dvec2 &q) {
  const glm::dvec2 p0(drawn.p[0]), p1(drawn.p[1]), p2(drawn.p[2]);
  const double area = cross(p1 - p0, p2 - p0);
  const double l1 = cross(q - p0, p2 - p0) / area, l2 = cross(p1 - p0, q - p0) / area;
  const double d0 = drawn.depth[0];
  return d0 + l1 * (drawn.depth[1] - d0) + l2 * (drawn.depth[2] - d0);
}

}  // namespace

void step4_triangles(const FrameGeometry &frame, const Scene &scene, const ProjectedObject &object,
                     const glm::uvec3 &triangle, std::vector<DrawnTriangle> &out) {
  out.clear();
  const float width = static_cast<float>(scene.width), height = static_cast<float>(scene.height);
  const unsigned a = object.outside[triangle.x], b = object.outside[triangle.y],
                 c = object.outside[triangle.z];
  if ((a | b | c) == 0) {
    add_drawn(object.screen[triangle.x], object.screen[triangle.y], object.screen[triangle.z],
              width, height, out);
    return;
  }
  if ((a & b & c) != 0) return;
  std::vector<ClipVertex> polygon, scratch;
  for (unsigned index : {triangle.x, triangle.y, triangle.z}) {
    polygon.push_back({{}, object.world[index], {}});
  }
  std::vector<GrVertex> screen;
  project_camera_polygon(frame, scene, polygon, scratch, screen);
  for (std::size_t i = 2; i < screen.size(); ++i) {
    add_drawn(screen[0], screen[i - 1], screen[i], width, height, out);
  }
}

void cut_along_drawn(const std::vector<GrVertex> &polygon, const std::vector<DrawnTriangle> &drawn,
                     bool q_is_oow, std::vector<std::vector<GrVertex>> &out) {
  glm::dvec2 low(INFINITY), high(-INFINITY);
  std::vector<CutVertex> source;
  for (const GrVertex &v : polygon) {
    const glm::dvec2 p(v.x, v.y);
    low = glm::min(low, p), high = glm::max(high, p);
    source.push_back({p, v.oow, v.a, v.tmuvtx[0].sow, v.tmuvtx[0].tow, v.tmuvtx[0].oow});
  }
  std::vector<CutVertex> part, scratch;
  for (const DrawnTriangle &triangle : drawn) {
    const glm::dvec2 box_low = glm::min(glm::min(glm::dvec2(triangle.p[0]), glm::dvec2(triangle.p[1])),
                                        glm::dvec2(triangle.p[2]));
    const glm::dvec2 box_high = glm::max(glm::max(glm::dvec2(triangle.p[0]), glm::dvec2(triangle.p[1])),
                                         glm::dvec2(triangle.p[2]));
    if (box_low.x > high.x || box_high.x < low.x || box_low.y > high.y || box_high.y < low.y) continue;
    part = source;
    for (int k = 0; k < 3 && part.size() >= 3; ++k) {
      cut(part, edge_line(triangle.p[k], triangle.p[(k + 1) % 3], triangle.p[(k + 2) % 3]), scratch);
    }
    std::vector<GrVertex> piece;
    for (const CutVertex &v : part) {
      GrVertex g = polygon.front();  // the fields no pass reads stay those of the piece
      g.x = snap(static_cast<float>(v.p.x)), g.y = snap(static_cast<float>(v.p.y));
      if (!piece.empty() && piece.back().x == g.x && piece.back().y == g.y) continue;
      const double oow = depth_at(triangle, glm::dvec2(g.x, g.y));
      const double scale = q_is_oow ? oow / v.oow : 1.0;
      g.oow = static_cast<float>(oow);
      g.a = static_cast<float>(v.a);
      g.tmuvtx[0].sow = static_cast<float>(v.sow * scale);
      g.tmuvtx[0].tow = static_cast<float>(v.tow * scale);
      g.tmuvtx[0].oow = static_cast<float>(v.q);
      piece.push_back(g);
    }
    while (piece.size() > 1 && piece.back().x == piece.front().x && piece.back().y == piece.front().y) {
      piece.pop_back();
    }
    float area = 0.0f;  // twice the signed area, screen pixels
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const GrVertex &p = piece[i], &q = piece[(i + 1) % piece.size()];
      area += p.x * q.y - q.x * p.y;
    }
    if (piece.size() >= 3 && area != 0.0f) out.push_back(std::move(piece));
  }
}

}  // namespace gs
