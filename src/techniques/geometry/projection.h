// From world space to Glide's screen: camera and light matrices, homogeneous clipping of
// polygons against planes (near plane, guard band, the light's frustum), and the screen mapping
// Glide expects (pixels from the upper-left corner, oow = 1/w).
#pragma once

#include "scene/scene.h"

#include <glide.h>
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace gs {

// A polygon vertex during clipping: its position in some clip space and its world position,
// which is what later passes re-project (everything else is derived from it).
struct ClipVertex {
  glm::vec4 clip;   // homogeneous clip coordinates (GL convention: visible when |x|,|y|,|z| <= w)
  glm::vec3 world;  // world space
  glm::vec4 extra;  // an attribute clipped along (e.g. colour), interpolated linearly
};

// Keeps the part of `polygon` where dot(plane, clip) >= 0. Attributes interpolate linearly in
// clip space, which is linear in world space, so the result is exact.
void clip_polygon(std::vector<ClipVertex> &polygon, const glm::vec4 &plane,
                  std::vector<ClipVertex> &scratch);

glm::mat4 camera_view(const Camera &camera);
glm::mat4 camera_projection(const Camera &camera, int width, int height);

// Screen mapping of a clip-space point with w > 0: Glide x, y in pixels (upper-left origin),
// oow = 1/w. Other GrVertex fields are zero.
GrVertex to_screen(const glm::vec4 &clip, int width, int height);

// A Glide screen coordinate (pixels) as the Voodoo's 12.4 set-up and the shim use it: to the
// nearest 1/16 pixel, halves away from zero: std::round(pixels * 16) / 16 to the bit (the sign
// of a zero too), without its library call (a build without SSE4.1 has no rounding
// instruction; the edge-error budget snaps every corner of the frame). Below 2^23 sixteenths
// the truncation is exact in an int32 and so is the fraction left; from there on every float
// is whole (and infinities and NaN pass through).
inline float snap_to_subpixel(float pixels) {
  const float sixteenths = pixels * 16.0f;
  if (!(std::fabs(sixteenths) < 8388608.0f)) return sixteenths / 16.0f;
  const float whole = static_cast<float>(static_cast<std::int32_t>(sixteenths));  // toward 0
  const float fraction = sixteenths - whole;
  const float rounded = fraction >= 0.5f ? whole + 1.0f : fraction <= -0.5f ? whole - 1.0f : whole;
  return std::copysign(rounded, sixteenths) / 16.0f;
}

// The planes a camera-space polygon is clipped to before projection: the near plane, and a
// guard band of `guard` screens around the view so coordinates stay well inside Glide's
// 12.4 fixed-point range (the clip window then trims exactly, as on the hardware).
std::vector<glm::vec4> camera_clip_planes(float guard);

}  // namespace gs
