// The budget of the error along a frame's shadow edges (shadow_edge_error.h): the screen
// pixels the error measure counts, found by covering each pixel centre that some object's
// camera-facing triangle holds with its corners snapped to 1/16 px as the Voodoo draws it
// (Glide screen, pixels); and the whole pixels 0.1% of them allows.
#include "techniques/texel_error/shadow_edge_error.h"

#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gs {
namespace {

// Marks in `covered` (width x height, rows in Glide screen y) the pixels whose centre (x + 0.5,
// y + 0.5) lies in the convex screen polygon `polygon` (pixels, already clipped to the screen).
// A centre on a level side counts where the shim's rasterizer draws it: on the polygon's
// bottom side (largest y), not its top (a floor's far triangles snapped to one row's centres).
void cover_convex_polygon(const std::vector<glm::vec2> &polygon, int width, int height,
                          std::vector<std::uint8_t> &covered) {
  if (polygon.size() < 3) return;
  float low = INFINITY, high = -INFINITY;
  for (const glm::vec2 &p : polygon) low = std::min(low, p.y), high = std::max(high, p.y);
  // The rows whose centre y + 0.5 has low < y + 0.5 <= high.
  const int first_row = std::max(static_cast<int>(std::floor(low - 0.5f)) + 1, 0);
  const int last_row = std::min(static_cast<int>(std::floor(high - 0.5f)) + 1, height);  // past the end
  for (int y = first_row; y < last_row; ++y) {
    const float centre = static_cast<float>(y) + 0.5f;
    float left = INFINITY, right = -INFINITY;  // where the row's centre line crosses the sides
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const glm::vec2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
      if ((p.y < centre) == (q.y < centre)) continue;
      const float x = p.x + (centre - p.y) * (q.x - p.x) / (q.y - p.y);
      left = std::min(left, x), right = std::max(right, x);
    }
    if (!(left < right)) continue;
    const int from = std::max(static_cast<int>(std::ceil(left - 0.5f)), 0);
    const int to = std::min(static_cast<int>(std::ceil(right - 0.5f)), width);  // past the end
    if (from >= to) continue;
    std::uint8_t *row = covered.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    std::fill(row + from, row + to, std::uint8_t{1});
  }
}

}  // namespace

float receiver_screen_pixels(const Scene &scene, const FrameGeometry &frame) {
  const int width = scene.width, height = scene.height;
  const float right = static_cast<float>(width), top = static_cast<float>(height);
  // The screen's sides as half-planes (x, y, 1) . side >= 0 (Glide screen, pixels).
  const glm::vec3 sides[4] = {{1, 0, 0}, {-1, 0, right}, {0, 1, 0}, {0, -1, top}};
  // Per pixel: some camera-facing triangle covers its centre. A pixel two objects cover (the
  // floor behind a wall) counts once, as the error measure counts the surface seen there.
  // Covered by the triangles snapped, as the frame draws them: the measure leaves out a pixel
  // the truth sees and the frame leaves as background (compare_masks' undrawn pixels: a floor
  // seen 7 cm above it, its far triangles thinner than the snap, planar19_camera_7cm_160x120:
  // 9 of 487). The pixels the snap adds beyond the exact outline (a centre within 1/32 px of
  // it) are counted too; covering the exact triangles as well to leave those out cost 8.5 M
  // instructions of the demo's shadowed frame and moved no budget of the project's scenes.
  const std::size_t count = static_cast<std::size_t>(std::max(width, 0)) *
                            static_cast<std::size_t>(std::max(height, 0));
  std::vector<std::uint8_t> drawn(count, 0);
  std::vector<glm::vec2> polygon, clipped;
  std::vector<ClipVertex> camera_polygon, scratch;
  std::vector<GrVertex> screen;
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::uvec3 &t : object.object->mesh.triangles) {
      const glm::vec3 &a = object.world[t.x], &b = object.world[t.y], &c = object.world[t.z];
      if (glm::dot(glm::cross(b - a, c - a), scene.camera.position - a) <= 0.0f) continue;
      polygon.clear();
      if ((object.outside[t.x] | object.outside[t.y] | object.outside[t.z]) == 0) {
        for (unsigned i : {t.x, t.y, t.z}) polygon.emplace_back(object.screen[i].x, object.screen[i].y);
      } else {  // through the camera's near plane and guard band first
        camera_polygon = {{{}, a, {}}, {{}, b, {}}, {{}, c, {}}};
        project_camera_polygon(frame, scene, camera_polygon, scratch, screen);
        for (const GrVertex &v : screen) polygon.emplace_back(v.x, v.y);
      }
      // Wholly on the screen (most triangles): clipping would keep the polygon as it is.
      const bool on_screen = std::all_of(polygon.begin(), polygon.end(), [&](const glm::vec2 &p) {
        return p.x >= 0.0f && p.x <= right && p.y >= 0.0f && p.y <= top;
      });
      for (const glm::vec3 &side : sides) {  // Sutherland-Hodgman
        if (on_screen) break;
        clipped.clear();
        for (std::size_t i = 0; i < polygon.size(); ++i) {
          const glm::vec2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
          const float dp = glm::dot(side, glm::vec3(p, 1.0f)), dq = glm::dot(side, glm::vec3(q, 1.0f));
          if (dp >= 0.0f) clipped.push_back(p);
          if ((dp >= 0.0f) != (dq >= 0.0f)) clipped.push_back(p + (q - p) * (dp / (dp - dq)));
        }
        polygon.swap(clipped);
      }
      for (glm::vec2 &p : polygon) p = {snap_to_subpixel(p.x), snap_to_subpixel(p.y)};
      cover_convex_polygon(polygon, width, height, drawn);
    }
  }
  return static_cast<float>(std::count(drawn.begin(), drawn.end(), std::uint8_t{1}));
}

float edge_error_budget(const Scene &scene, const FrameGeometry &frame) {
  // A pixel centre is on one side of a shadow's edge or the other: the measure counts whole
  // pixels, so a frame whose 0.1% is under one pixel may hold none.
  return std::floor(kEdgeErrorReceiverShare * receiver_screen_pixels(scene, frame));
}

}  // namespace gs
