// Step 4's triangles as the shim rasterises them, and clipped receiver pieces cut along them
// with their depth on those triangles' planes (receiver_depth_planes.h). Spaces: Glide screen
// (pixels, y down); depth the W buffer's unbiased 1/w.
#include "techniques/projected/receiver_depth_planes.h"
#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>

namespace gs {
namespace {

// A corner as the shim holds it: x, y snapped, depth clamped, all float; its clip-window
// clipping interpolates them in float (glide_shim/src/clip.cpp), which this follows to the bit.
struct Corner {
  float x, y, depth;
};

Corner corner_of(const GrVertex &v) {
  return {snap_to_subpixel(v.x), snap_to_subpixel(v.y), std::clamp(std::min(v.oow, 1.0f), 0.0f, 1.0f)};
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
    for (Corner &v : polygon) v.x = snap_to_subpixel(v.x), v.y = snap_to_subpixel(v.y);
  }
  for (std::size_t i = 2; i < polygon.size(); ++i) {
    const Corner &p = polygon[0], &q = polygon[i - 1], &r = polygon[i];
    const float area = (q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y);
    if (!(area < 0.0f)) continue;  // zero area, or culled
    out.push_back({{{p.x, p.y}, {q.x, q.y}, {r.x, r.y}}, {p.depth, q.depth, r.depth}});
  }
}

// A vertex during the cut: its screen position and the light view position of the receiver's
// point seen there (the plane's values are affine in the light view, and their ratio to w is
// affine in the screen).
struct CutVertex {
  glm::dvec2 p;
  glm::dvec4 light_view;
  double oow;  // the point's true 1/w
};

double cross(const glm::dvec2 &u, const glm::dvec2 &v) { return u.x * v.y - u.y * v.x; }

bool before(const CutVertex &u, const CutVertex &v) {
  return u.p.x < v.p.x || (u.p.x == v.p.x && u.p.y < v.p.y);
}

// Keeps the part of `polygon` where dot(plane, light view position) >= 0. A segment is cut at
// the point found from its ends in a fixed order, so two pieces sharing it agree to the bit.
void cut(std::vector<CutVertex> &polygon, const glm::dvec4 &plane, std::vector<CutVertex> &scratch) {
  scratch.clear();
  const std::size_t n = polygon.size();
  auto value = [&](const CutVertex &v) { return glm::dot(plane, v.light_view) * v.oow; };  // affine
  for (std::size_t i = 0; i < n; ++i) {
    const CutVertex &p = polygon[i], &q = polygon[(i + 1) % n];
    const double dp = value(p), dq = value(q);
    if (dp >= 0.0) scratch.push_back(p);
    if ((dp > 0.0 && dq < 0.0) || (dp < 0.0 && dq > 0.0)) {
      const CutVertex &u = before(p, q) ? p : q, &v = before(p, q) ? q : p;
      const double du = value(u), dv = value(v);
      const double t = du / (du - dv);
      // Screen-space interpolation: light view position over w is affine there.
      const double oow = u.oow + (v.oow - u.oow) * t;
      scratch.push_back({u.p + (v.p - u.p) * t,
                         (u.light_view * u.oow + (v.light_view * v.oow - u.light_view * u.oow) * t) / oow,
                         oow});
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

ReceiverPlane::ReceiverPlane(const FrameGeometry &frame, const Scene &scene,
                             const glm::mat4 &light_view, const glm::vec3 &point,
                             const glm::vec3 &normal)
    : screen_to_world_(glm::inverse(glm::dmat4(frame.view_projection))),
      world_to_light_view_(light_view),
      camera_(frame.view_projection),
      point_(point),
      normal_(normal),
      pixels_(scene.width, scene.height) {}

bool ReceiverPlane::at(const glm::dvec2 &screen, glm::dvec4 &light_view, double &oow) const {
  const glm::dvec2 ndc(screen.x / pixels_.x * 2.0 - 1.0, 1.0 - screen.y / pixels_.y * 2.0);
  const glm::dvec4 near = screen_to_world_ * glm::dvec4(ndc, -1.0, 1.0);
  const glm::dvec4 far = screen_to_world_ * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 from = glm::dvec3(near) / near.w, to = glm::dvec3(far) / far.w;  // world
  const double along = glm::dot(normal_, to - from);
  if (!(std::abs(along) > 0.0)) return false;
  const glm::dvec3 world = from + (to - from) * (glm::dot(normal_, point_ - from) / along);
  const double w = (camera_ * glm::dvec4(world, 1.0)).w;
  if (!(w > 0.0)) return false;
  light_view = world_to_light_view_ * glm::dvec4(world, 1.0);
  oow = 1.0 / w;
  return true;
}

glm::vec3 ReceiverPlane::world(const glm::dvec4 &light_view) const {
  return glm::vec3(glm::inverse(world_to_light_view_) * light_view);
}

void cut_drawn(const std::vector<DrawnTriangle> &drawn, const ReceiverPlane &plane,
               const std::vector<glm::vec4> &light_view_planes, std::vector<DrawnPiece> &out) {
  std::vector<CutVertex> part, scratch;
  for (const DrawnTriangle &triangle : drawn) {
    part.clear();
    for (const glm::vec2 &corner : triangle.p) {
      CutVertex v{glm::dvec2(corner), {}, 0.0};
      if (!plane.at(v.p, v.light_view, v.oow)) break;
      part.push_back(v);
    }
    if (part.size() < 3) continue;
    for (const glm::vec4 &cut_plane : light_view_planes) {
      cut(part, glm::dvec4(cut_plane), scratch);
      if (part.size() < 3) break;
    }
    DrawnPiece piece;
    for (const CutVertex &v : part) {
      // Snapped as the shim snaps it; the depth step 4 drew there; the receiver's point there.
      const glm::vec2 snapped(snap_to_subpixel(static_cast<float>(v.p.x)), snap_to_subpixel(static_cast<float>(v.p.y)));
      if (!piece.empty() && piece.back().screen == snapped) continue;
      glm::dvec4 light_view;
      double oow;
      if (!plane.at(glm::dvec2(snapped), light_view, oow)) light_view = v.light_view;
      piece.push_back({snapped, static_cast<float>(depth_at(triangle, glm::dvec2(snapped))),
                       plane.world(light_view)});
    }
    while (piece.size() > 1 && piece.back().screen == piece.front().screen) piece.pop_back();
    float area = 0.0f;  // twice the signed area, screen pixels
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const glm::vec2 &p = piece[i].screen, &q = piece[(i + 1) % piece.size()].screen;
      area += p.x * q.y - q.x * p.y;
    }
    if (piece.size() >= 3 && area != 0.0f) out.push_back(std::move(piece));
  }
}

}  // namespace gs
