// Triangles in a bounding-volume hierarchy for the depth map's replay (triangle_bvh.h).
// Space: world (boxes, rays; double); ray parameters in units of the ray's direction.
#include "techniques/depth_map/triangle_bvh.h"

#include "techniques/geometry/line_triangle.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gs::depth_map {

bool ray_meets_triangle(const glm::dvec3 &o, const glm::dvec3 &d, const glm::dvec3 &a,
                        const glm::dvec3 &b, const glm::dvec3 &c, double &t) {
  return line_meets_triangle(o, d, a, b - a, c - a, t, 1e-300);
}

namespace {

constexpr std::uint32_t kLeafSize = 4;  // triangles a leaf holds at most
// The deepest a median split goes for 2^32 triangles, and the stack a walk needs for it.
constexpr int kStackSize = 64;

}  // namespace

TriangleBvh::TriangleBvh(std::vector<glm::dvec3> corners) : corners_(std::move(corners)) {
  const std::uint32_t count = static_cast<std::uint32_t>(corners_.size() / 3);
  if (count == 0) return;
  // The boxes are padded by a millionth of the largest coordinate (metres): a hit the test
  // reports lies on its triangle within rounding (~1e-16 of the coordinates), even for a ray at
  // a millionth of a radian to its plane, so no box a hit lies in is passed by.
  double largest = 0.0;
  for (const glm::dvec3 &p : corners_) {
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  pad_ = 1e-6 * largest + 1e-12;
  order_.resize(count);
  centres_.resize(count);
  for (std::uint32_t k = 0; k < count; ++k) {
    order_[k] = k;
    const glm::dvec3 &a = corners_[3 * k], &b = corners_[3 * k + 1], &c = corners_[3 * k + 2];
    centres_[k] = 0.5 * (glm::min(a, glm::min(b, c)) + glm::max(a, glm::max(b, c)));
  }
  nodes_.reserve(2 * (count / kLeafSize + 1));
  build(0, count);
  centres_ = {};
}

std::uint32_t TriangleBvh::build(std::uint32_t begin, std::uint32_t end) {
  const std::uint32_t at = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  glm::dvec3 low(INFINITY), high(-INFINITY), centre_low(INFINITY), centre_high(-INFINITY);
  for (std::uint32_t k = begin; k < end; ++k) {
    for (int m = 0; m < 3; ++m) {
      low = glm::min(low, corners_[3 * order_[k] + m]);
      high = glm::max(high, corners_[3 * order_[k] + m]);
    }
    centre_low = glm::min(centre_low, centres_[order_[k]]);
    centre_high = glm::max(centre_high, centres_[order_[k]]);
  }
  nodes_[at].low = low - pad_;
  nodes_[at].high = high + pad_;
  const glm::dvec3 spread = centre_high - centre_low;
  const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;
  if (end - begin <= kLeafSize || !(spread[axis] > 0.0)) {
    nodes_[at].first = begin, nodes_[at].count = end - begin;
    return at;
  }
  // The median by box centre along the widest axis (ties by index, so the tree is one tree).
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](std::uint32_t x, std::uint32_t y) {
                     const double cx = centres_[x][axis], cy = centres_[y][axis];
                     return cx < cy || (cx == cy && x < y);
                   });
  build(begin, middle);
  const std::uint32_t second = build(middle, end);
  nodes_[at].first = second;
  return at;
}

bool TriangleBvh::passes(const Node &node, const glm::dvec3 &o, const glm::dvec3 &d,
                         const glm::dvec3 &inverse, double from, double to,
                         double &entry) const {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-300) {  // along the slab: within it or never (moves < 1e-300)
      if (o[k] < node.low[k] || o[k] > node.high[k]) return false;
      continue;
    }
    double near = (node.low[k] - o[k]) * inverse[k], far = (node.high[k] - o[k]) * inverse[k];
    if (near > far) std::swap(near, far);
    from = std::max(from, near), to = std::min(to, far);
    if (from > to) return false;
  }
  entry = from;
  return true;
}

bool TriangleBvh::meets(std::uint32_t triangle, const glm::dvec3 &o, const glm::dvec3 &d,
                        double &t) const {
  const std::size_t k = 3 * static_cast<std::size_t>(triangle);
  return ray_meets_triangle(o, d, corners_[k], corners_[k + 1], corners_[k + 2], t);
}

bool TriangleBvh::nearest(const glm::dvec3 &o, const glm::dvec3 &d, double low, double &high,
                          std::size_t &hit) const {
  if (nodes_.empty()) return false;
  const glm::dvec3 inverse = 1.0 / d;
  bool found = false;
  double entry = 0.0;
  std::uint32_t stack[kStackSize];
  int size = 0;
  if (passes(nodes_[0], o, d, inverse, low, high, entry)) stack[size++] = 0;
  while (size > 0) {
    const Node &node = nodes_[stack[--size]];
    // Closed at `high`: a triangle at the same parameter but earlier in the list wins.
    if (!passes(node, o, d, inverse, low, high, entry)) continue;
    if (node.count > 0) {
      for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
        double t = 0.0;
        if (!meets(order_[k], o, d, t) || !(t > low)) continue;
        if (t < high || (found && t == high && order_[k] < hit)) {
          high = t, hit = order_[k], found = true;
        }
      }
      continue;
    }
    // The nearer child is walked first (pushed last), so the farther one is often passed by.
    const std::uint32_t first = static_cast<std::uint32_t>(&node - nodes_.data()) + 1, second = node.first;
    double first_entry = 0.0, second_entry = 0.0;
    const bool first_passes = passes(nodes_[first], o, d, inverse, low, high, first_entry);
    const bool second_passes = passes(nodes_[second], o, d, inverse, low, high, second_entry);
    if (first_passes && second_passes) {
      const bool first_nearer = first_entry <= second_entry;
      stack[size++] = first_nearer ? second : first;
      stack[size++] = first_nearer ? first : second;
    } else if (first_passes) {
      stack[size++] = first;
    } else if (second_passes) {
      stack[size++] = second;
    }
  }
  return found;
}

bool TriangleBvh::any(const glm::dvec3 &o, const glm::dvec3 &d, double low, double high,
                      bool facing_only) const {
  if (nodes_.empty()) return false;
  const glm::dvec3 inverse = 1.0 / d;
  double entry = 0.0;
  std::uint32_t stack[kStackSize];
  int size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const Node &node = nodes_[stack[--size]];
    if (!passes(node, o, d, inverse, low, high, entry)) continue;
    if (node.count == 0) {
      stack[size++] = node.first;
      stack[size++] = static_cast<std::uint32_t>(&node - nodes_.data()) + 1;
      continue;
    }
    for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
      if (facing_only) {
        const std::size_t c = 3 * static_cast<std::size_t>(order_[k]);
        const glm::dvec3 face = glm::cross(corners_[c + 1] - corners_[c], corners_[c + 2] - corners_[c]);
        if (!(glm::dot(face, d) < 0.0)) continue;
      }
      double t = 0.0;
      if (meets(order_[k], o, d, t) && t > low && t < high) return true;
    }
  }
  return false;
}

}  // namespace gs::depth_map
