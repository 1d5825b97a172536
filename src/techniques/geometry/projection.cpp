// Projection and polygon clipping shared by every pass that draws through a camera or a light.
#include "techniques/geometry/projection.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <tuple>

namespace gs {

void clip_polygon(std::vector<ClipVertex> &polygon, const glm::vec4 &plane,
                  std::vector<ClipVertex> &scratch) {
  // Wholly inside (most calls): the loop below would copy every vertex as it is.
  bool inside = true;
  for (const ClipVertex &v : polygon) inside = inside && glm::dot(plane, v.clip) >= 0.0f;
  if (inside) return;
  scratch.clear();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const ClipVertex &a = polygon[i];
    const ClipVertex &b = polygon[(i + 1) % n];
    const float da = glm::dot(plane, a.clip), db = glm::dot(plane, b.clip);
    if (da >= 0.0f) scratch.push_back(a);
    if ((da >= 0.0f) != (db >= 0.0f)) {
      // From the same end of the edge whichever way it is walked, so that two polygons sharing
      // the edge (neighbouring triangles) get the very same point and leave no crack between.
      const bool forward = std::tie(a.clip.x, a.clip.y, a.clip.z, a.clip.w) <
                           std::tie(b.clip.x, b.clip.y, b.clip.z, b.clip.w);
      const ClipVertex &p = forward ? a : b, &q = forward ? b : a;
      const float dp = forward ? da : db, dq = forward ? db : da;
      const float t = dp / (dp - dq);
      scratch.push_back({p.clip + (q.clip - p.clip) * t, p.world + (q.world - p.world) * t,
                         p.extra + (q.extra - p.extra) * t});
    }
  }
  polygon.swap(scratch);
}

glm::mat4 camera_view(const Camera &camera) {
  return glm::lookAt(camera.position, camera.target, camera.up);
}

glm::mat4 camera_projection(const Camera &camera, int width, int height) {
  // Divided by the near distance, so clip w counts near-plane distances rather than metres:
  // everything drawn has w >= 1, the range of Glide's W-buffer (it stores 1/w in [0, 1], so in
  // metres all that is nearer than 1 m would share the nearest depth, and a scene scaled down
  // would have no depth order at all). A homogeneous factor moves no projected point.
  return glm::perspective(glm::radians(camera.fov_degrees),
                          static_cast<float>(width) / static_cast<float>(height),
                          camera.near_plane, camera.far_plane) /
         camera.near_plane;
}

GrVertex to_screen(const glm::vec4 &clip, int width, int height) {
  GrVertex v;
  std::memset(&v, 0, sizeof v);
  const float oow = 1.0f / clip.w;
  v.x = (clip.x * oow * 0.5f + 0.5f) * static_cast<float>(width);
  v.y = (0.5f - clip.y * oow * 0.5f) * static_cast<float>(height);
  v.oow = oow;
  return v;
}

std::vector<glm::vec4> camera_clip_planes(float guard) {
  return {
      {0.0f, 0.0f, 1.0f, 1.0f},     // near: z >= -w
      {-1.0f, 0.0f, 0.0f, guard},   // x <= guard * w
      {1.0f, 0.0f, 0.0f, guard},    // x >= -guard * w
      {0.0f, -1.0f, 0.0f, guard},
      {0.0f, 1.0f, 0.0f, guard},
  };
}

}  // namespace gs
