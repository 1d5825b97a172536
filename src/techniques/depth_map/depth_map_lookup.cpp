// The receiver-plane bias of the depth map's lookup (depth_map_lookup.h). Spaces: world (the
// corners); light texture coordinates (s, t, r, q) and the map's window space (s/q and t/q in
// texels, r/q the stored depth 0..1), in which a triangle's depth is a plane. The plane is found
// from the homogeneous corners (s and t scaled to texels), so a triangle reaching behind the
// light's plane (q <= 0 at a corner: a long wall beside the light) gets it too.
#include "techniques/depth_map/depth_map_lookup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace gs::depth_map {
namespace {

using Corner = std::array<double, 4>;  // S = s * side, T = t * side, r, q

double det3(double a, double b, double c, double d, double e, double f, double g, double h,
            double i) {
  return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}

// The part of the polygon `in` where dot(plane, corner) >= 0 (homogeneous, so a plane through
// the light clips the window-space image without dividing by q).
std::vector<Corner> clipped(const std::vector<Corner> &in, const Corner &plane) {
  std::vector<Corner> out;
  auto side = [&](const Corner &c) {
    return plane[0] * c[0] + plane[1] * c[1] + plane[2] * c[2] + plane[3] * c[3];
  };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Corner &a = in[i], &b = in[(i + 1) % in.size()];
    const double da = side(a), db = side(b);
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) {
      const double k = da / (da - db);
      Corner c;
      for (int j = 0; j < 4; ++j) c[j] = a[j] + k * (b[j] - a[j]);
      out.push_back(c);
    }
  }
  return out;
}

// The triangle's span of r/q over its part inside the map (0 <= s/q, t/q <= side, which puts
// q >= 0): only there can it have drawn the texels it reads. Infinite where that part reaches
// the light's plane (depth without bound), 0 when nothing is inside.
double span_in_map(const std::vector<Corner> &triangle, double side) {
  std::vector<Corner> part = triangle;
  for (const Corner &plane : {Corner{1, 0, 0, 0}, Corner{-1, 0, 0, side}, Corner{0, 1, 0, 0},
                              Corner{0, -1, 0, side}}) {
    part = clipped(part, plane);
    if (part.empty()) return 0.0;
  }
  double low = INFINITY, high = -INFINITY;
  for (const Corner &c : part) {
    if (!(c[3] > 0.0)) return INFINITY;
    low = std::min(low, c[2] / c[3]);
    high = std::max(high, c[2] / c[3]);
  }
  return high - low;
}

}  // namespace

std::vector<glm::vec4> biased_map_coords(const std::vector<glm::vec3> &corners,
                                         const glm::mat4 &to_map, int side, float factor) {
  std::vector<glm::vec4> coords;
  coords.reserve(corners.size());
  for (const glm::vec3 &p : corners) coords.push_back(to_map * glm::vec4(p, 1.0f));
  if (!(factor > 0.0f)) return coords;
  const double texels = static_cast<double>(side);
  for (std::size_t first = 0; first + 2 < coords.size(); first += 3) {
    glm::vec4 *c = &coords[first];
    std::vector<Corner> h(3);
    for (int i = 0; i < 3; ++i) {
      // Each corner scaled to unit size: the same point, and the determinants stay in range.
      const double scale = std::max({std::abs(double{c[i].x}) * texels,
                                     std::abs(double{c[i].y}) * texels, std::abs(double{c[i].w}),
                                     1e-30});
      h[i] = {c[i].x * texels / scale, c[i].y * texels / scale, c[i].z / scale, c[i].w / scale};
    }
    // No more than the triangle's own depth span: a triangle the light sees (nearly) edge-on
    // covers a sliver of a texel, and the texels around it hold other surfaces, which its own
    // slope says nothing about (waves under an 8-degree light: 0.2% false light without this).
    const double span = span_in_map(h, texels);
    // Its window-space plane r/q = gx s/q + gy t/q + z0 through the homogeneous corners:
    // r = gx S + gy T + z0 q at each, by Cramer's rule. A zero determinant: the light sees the
    // triangle edge-on (its plane passes through the light).
    const double det = det3(h[0][0], h[0][1], h[0][3], h[1][0], h[1][1], h[1][3], h[2][0],
                            h[2][1], h[2][3]);
    double lowered = span;
    if (std::abs(det) > 1e-12) {
      const double gx = det3(h[0][2], h[0][1], h[0][3], h[1][2], h[1][1], h[1][3], h[2][2],
                             h[2][1], h[2][3]) / det;  // depth per texel along s
      const double gy = det3(h[0][0], h[0][2], h[0][3], h[1][0], h[1][2], h[1][3], h[2][0],
                             h[2][2], h[2][3]) / det;  // along t
      lowered = std::min(factor * (std::abs(gx) + std::abs(gy)), span);
    }
    if (!std::isfinite(lowered)) lowered = 0.0;
    // r/q lowered by `lowered` wherever q is not 0 (behind the light the q gate decides).
    for (int i = 0; i < 3; ++i) c[i].z -= static_cast<float>(lowered) * c[i].w;
  }
  return coords;
}

}  // namespace gs::depth_map
