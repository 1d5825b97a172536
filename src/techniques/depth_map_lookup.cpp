// The receiver-plane bias of the depth map's lookup (depth_map_lookup.h). Spaces: world (the
// corners); light texture coordinates (s, t, r, q) and the map's window space (s/q and t/q in
// texels, r/q the stored depth 0..1), in which a triangle's depth is a plane.
#include "techniques/depth_map_lookup.h"

#include <algorithm>
#include <cmath>

namespace gs::depth_map {

std::vector<glm::vec4> biased_map_coords(const std::vector<glm::vec3> &corners,
                                         const glm::mat4 &to_map, int side, float factor) {
  std::vector<glm::vec4> coords;
  coords.reserve(corners.size());
  for (const glm::vec3 &p : corners) coords.push_back(to_map * glm::vec4(p, 1.0f));
  if (!(factor > 0.0f)) return coords;
  const float texels = static_cast<float>(side);
  for (std::size_t first = 0; first + 2 < coords.size(); first += 3) {
    glm::vec4 *c = &coords[first];
    if (!(c[0].w > 0.0f && c[1].w > 0.0f && c[2].w > 0.0f)) continue;
    // Window space: x, y in texels, z the depth the map stores.
    glm::vec3 w[3];
    for (int i = 0; i < 3; ++i) w[i] = glm::vec3(c[i].x * texels, c[i].y * texels, c[i].z) / c[i].w;
    const glm::vec3 u = w[1] - w[0], v = w[2] - w[0];
    const float det = u.x * v.y - v.x * u.y;  // twice the triangle's area in texels
    // No more than the triangle's own depth span: a triangle the light sees (nearly) edge-on
    // covers a sliver of a texel, and the texels around it hold other surfaces, which its own
    // slope says nothing about (waves under an 8-degree light: 0.2% false light without this).
    const float span = std::max({w[0].z, w[1].z, w[2].z}) - std::min({w[0].z, w[1].z, w[2].z});
    float lowered = span;
    if (std::abs(det) > 1e-12f) {
      const float gx = (u.z * v.y - v.z * u.y) / det;  // depth per texel along s
      const float gy = (u.x * v.z - v.x * u.z) / det;  // along t
      lowered = std::min(factor * (std::abs(gx) + std::abs(gy)), span);
    }
    if (!std::isfinite(lowered)) lowered = 0.0f;
    for (int i = 0; i < 3; ++i) c[i].z -= lowered * c[i].w;  // r/q lowered by `lowered`
  }
  return coords;
}

}  // namespace gs::depth_map
