// Where a shadow texture's edge, strayed from the true shadow edge, lands on a receiver's plane
// (world) and on the screen (pixels), and how much of that stray the screen shows
// (shadow_edge_error.cpp).
#pragma once

#include "techniques/geometry/line_triangle.h"
#include "techniques/texel_error/texel_footprint.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace gs {

// Narrows [from, to] (parameters along a segment) to where a linear function with values
// `at_from_end` at 0 and `at_to_end` at 1 is at least 0.
inline void keep_non_negative(float at_from_end, float at_to_end, float &from, float &to) {
  if (at_from_end < 0.0f && at_to_end < 0.0f) {
    from = 1.0f, to = 0.0f;
  } else if (at_from_end < 0.0f) {
    from = std::max(from, at_from_end / (at_from_end - at_to_end));
  } else if (at_to_end < 0.0f) {
    to = std::min(to, at_from_end / (at_from_end - at_to_end));
  }
}

// The receiver plane through `origin` (world) with unit tangents t1, t2, seen from the light: a
// point of the light's texture (texels, x right, y down) back on the plane and on to the screen
// (pixels, footprint_screen_pixels). The light's projection restricted to the plane is a
// homography, inverted once per plane, so a texture edge strayed from the true one lands where
// the texels' own stretch puts it: farther from the light a texel spans more of a grazed plane
// than the Jacobian at the true edge says (issue 14: a wall's shadow thrown 7 m along a floor
// from a light 1 m up, tests/hard_cases/audit/ne1).
struct PlaneFromTexture {
  glm::mat3 plane_from_ndc{1.0f};  // light NDC (x, y, 1) to plane (a, b, 1), up to scale
  glm::vec3 origin{0.0f}, t1{0.0f}, t2{0.0f};
  bool usable = false;

  PlaneFromTexture(const FootprintSpace &space, const glm::vec3 &origin_, const glm::vec3 &t1_,
                   const glm::vec3 &t2_)
      : origin(origin_), t1(t1_), t2(t2_) {
    auto xyw = [&](const glm::vec4 &v) {
      const glm::vec4 c = space.light_clip * v;
      return glm::vec3(c.x, c.y, c.w);
    };
    const glm::mat3 ndc_from_plane(xyw(glm::vec4(t1, 0.0f)), xyw(glm::vec4(t2, 0.0f)),
                                   xyw(glm::vec4(origin, 1.0f)));
    usable = std::abs(glm::determinant(ndc_from_plane)) > 1e-12f;
    if (usable) plane_from_ndc = glm::inverse(ndc_from_plane);
  }
  // False where the texel's ray from the light misses the plane before it, or the point is
  // behind the camera: no screen position.
  bool screen_of(const FootprintSpace &space, const glm::vec2 &texel, glm::vec2 &screen) const {
    glm::vec3 world;
    return screen_of(space, texel, screen, world);
  }
  // The same, with the point on the plane (world) too.
  bool screen_of(const FootprintSpace &space, const glm::vec2 &texel, glm::vec2 &screen,
                 glm::vec3 &world) const {
    if (!usable) return false;
    const glm::vec2 ndc(texel.x / space.texels * 2.0f - 1.0f, 1.0f - texel.y / space.texels * 2.0f);
    const glm::vec3 abw = plane_from_ndc * glm::vec3(ndc, 1.0f);
    if (!(abw.z > 0.0f)) return false;  // the light's w there, inverted: the plane behind it
    world = origin + (abw.x / abw.z) * t1 + (abw.y / abw.z) * t2;
    const glm::vec4 c = space.camera_clip * glm::vec4(world, 1.0f);
    if (!(c.w > 0.0f)) return false;
    screen = footprint_screen_pixels(space, world);
    return true;
  }
};

// Whether the segment from `from` to `to` (world) passes through the triangle a, b, c (world)
// short of `to` (Moller and Trumbore), and not along its side a, b: the camera's view of a
// shadow edge's point blocked by the caster's face along the edge a, b (shadow_edge_error.cpp).
// A camera at the light sees every shadow edge along its silhouette edge, which hides nothing
// (Nguyen's Figure 8 from the light): a crossing within a thousandth of the face's extent of that
// side (its barycentric weight of c) is not counted, nor one that rounding puts there.
inline bool segment_crosses_triangle(const glm::vec3 &from, const glm::vec3 &to,
                                     const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c) {
  constexpr float kOffSide = 1e-3f;
  float t = 0.0f;
  return line_meets_triangle(from, to - from, a, b - a, c - a, t, 1e-12f, kOffSide) && t > 0.0f &&
         t < 0.999f;
}

// The screen's sides as camera clip planes, kept where dot(side, clip) >= 0: x and y within w.
inline const glm::vec4 kScreenSides[4] = {{1, 0, 0, 1}, {-1, 0, 0, 1}, {0, 1, 0, 1}, {0, -1, 0, 1}};

// True when the polygon side p to q (world) lies along one of the screen's sides: a side the
// polygon was clipped at to keep what the screen shows (texel_footprint), not the receiver's
// own border. The receiver goes on beyond it.
inline bool along_screen_side(const FootprintSpace &space, const glm::vec3 &p, const glm::vec3 &q) {
  const glm::vec4 cp = space.camera_clip * glm::vec4(p, 1.0f);
  const glm::vec4 cq = space.camera_clip * glm::vec4(q, 1.0f);
  for (const glm::vec4 &side : kScreenSides) {
    // Clip space: a clipped corner lies on its side within float rounding of its w.
    if (std::abs(glm::dot(side, cp)) <= 1e-4f * std::abs(cp.w) &&
        std::abs(glm::dot(side, cq)) <= 1e-4f * std::abs(cq.w)) {
      return true;
    }
  }
  return false;
}

// Screen pixels a point of the plane at `texel` (light screen texels) can move when the texture
// moves it up to two texels any way (texture_edge_offset's search reaches two texels): how far
// off the screen a true shadow edge can lie and its texture's edge still stray onto it. From
// the moves along the texture's axes, d = (a, b) with |J d| <= sqrt(|J (2, 0)|^2 + |J (0, 2)|^2)
// for the projection's near-linear J; zero where the point has no screen position.
inline float stray_reach_pixels(const FootprintSpace &space, const PlaneFromTexture &plane,
                                const glm::vec2 &texel) {
  glm::vec2 centre, moved;
  if (!plane.screen_of(space, texel, centre)) return 0.0f;
  float along_axis[2] = {0.0f, 0.0f};
  for (int axis = 0; axis < 2; ++axis) {
    for (float step : {-2.0f, 2.0f}) {
      glm::vec2 to = texel;
      to[axis] += step;
      if (plane.screen_of(space, to, moved)) {
        along_axis[axis] = std::max(along_axis[axis], glm::length(moved - centre));
      }
    }
  }
  return std::hypot(along_axis[0], along_axis[1]);
}

// The part of the screen segment a to b (pixels from the screen's centre, y up, as
// footprint_screen_pixels) on the screen (`half`: half its width and height), as parameters
// [from, to] along it: from >= to when none is.
inline glm::vec2 on_screen_part(const glm::vec2 &half, const glm::vec2 &a, const glm::vec2 &b) {
  float from = 0.0f, to = 1.0f;
  for (int axis = 0; axis < 2 && from < to; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {  // sign * x <= half
      keep_non_negative(half[axis] - sign * a[axis], half[axis] - sign * b[axis], from, to);
    }
  }
  return {from, to};
}

// Narrows [from, to] along the world segment a to b to where it lies before the camera's near
// plane and within `margin` pixels of the screen's sides (camera clip x within w (1 + 2 margin /
// width), y likewise), so that it has a screen position.
inline void keep_near_screen(const FootprintSpace &space, const glm::vec3 &a, const glm::vec3 &b,
                             float margin, float &from, float &to) {
  const glm::vec4 ca = space.camera_clip * glm::vec4(a, 1.0f);
  const glm::vec4 cb = space.camera_clip * glm::vec4(b, 1.0f);
  const glm::vec2 widen = 1.0f + 2.0f * margin / space.pixels;
  const glm::vec4 sides[5] = {{1, 0, 0, widen.x}, {-1, 0, 0, widen.x}, {0, 1, 0, widen.y},
                              {0, -1, 0, widen.y}, {0, 0, 1, 1}};
  for (const glm::vec4 &side : sides) {
    keep_non_negative(glm::dot(side, ca), glm::dot(side, cb), from, to);
  }
}

}  // namespace gs
