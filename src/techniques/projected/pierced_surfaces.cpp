// Receivers that are not planar, reached through by a caster (pierced_receivers.h): finding them
// in world space (an edge of either mesh through a triangle of the other, inside both meshes'
// bounds, through a grid of that box). Step 1's depth of their surface is
// receiver_mask_surface.cpp's.
#include "techniques/projected/pierced_receivers.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace gs {
namespace {

constexpr int kGrid = 8;  // cells a side of the world-space grid the triangles are sorted into

struct Triangle {
  glm::vec3 a, b, c;
  glm::vec3 normal;  // unit
  glm::vec3 low, high;
};

Triangle triangle_of(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float area = glm::length(n);
  return {a, b, c, area > 0.0f ? n / area : glm::vec3(0.0f), glm::min(a, glm::min(b, c)),
          glm::max(a, glm::max(b, c))};
}

// Whether the segment p..q passes through `t` from more than `tolerance` on one side of its
// plane to more than that on the other.
bool crosses(const Triangle &t, const glm::vec3 &p, const glm::vec3 &q, float tolerance) {
  const float dp = glm::dot(t.normal, p - t.a), dq = glm::dot(t.normal, q - t.a);
  if (!((dp > tolerance && dq < -tolerance) || (dp < -tolerance && dq > tolerance))) return false;
  const glm::vec3 x = p + (q - p) * (dp / (dp - dq));
  return glm::dot(glm::cross(t.b - t.a, x - t.a), t.normal) >= 0.0f &&
         glm::dot(glm::cross(t.c - t.b, x - t.b), t.normal) >= 0.0f &&
         glm::dot(glm::cross(t.a - t.c, x - t.c), t.normal) >= 0.0f;
}

// Triangles sorted into a kGrid^3 grid over a box (world space) by their bounds.
struct TriangleGrid {
  glm::vec3 low, cell;
  std::vector<std::vector<std::size_t>> cells =
      std::vector<std::vector<std::size_t>>(kGrid * kGrid * kGrid);
  // Clamped while still a float, so a point far outside the box gives an edge cell, not an
  // integer overflow.
  glm::ivec3 at(const glm::vec3 &p) const {
    return glm::ivec3(glm::clamp(glm::floor((p - low) / cell), glm::vec3(0.0f),
                                 glm::vec3(static_cast<float>(kGrid - 1))));
  }
  template <typename Visit>
  void each_cell(const glm::vec3 &from, const glm::vec3 &to, Visit visit) const {
    const glm::ivec3 first = at(from), last = at(to);
    for (int z = first.z; z <= last.z; ++z) {
      for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
          visit(cells[static_cast<std::size_t>((z * kGrid + y) * kGrid + x)]);
        }
      }
    }
  }
};

// The triangles of `world` (indexed by `triangles`) whose bounds meet the box keep_low..keep_high,
// sorted into a grid over the box low..high (world space); `index` maps each kept one back to its
// triangle.
TriangleGrid sort_triangles(const std::vector<glm::vec3> &world,
                            const std::vector<glm::uvec3> &triangles, const glm::vec3 &low,
                            const glm::vec3 &high, const glm::vec3 &keep_low,
                            const glm::vec3 &keep_high, std::vector<Triangle> &kept,
                            std::vector<std::size_t> &index) {
  TriangleGrid grid;
  grid.low = low;
  grid.cell = glm::max((high - low) / static_cast<float>(kGrid), glm::vec3(1e-12f));
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const glm::uvec3 &t = triangles[i];
    const glm::vec3 &a = world[t.x], &b = world[t.y], &c = world[t.z];
    if (glm::any(glm::lessThan(glm::max(a, glm::max(b, c)), keep_low)) ||
        glm::any(glm::lessThan(keep_high, glm::min(a, glm::min(b, c))))) {
      continue;
    }
    const Triangle triangle = triangle_of(a, b, c);
    if (triangle.normal == glm::vec3(0.0f)) continue;
    const glm::ivec3 first = grid.at(triangle.low), last = grid.at(triangle.high);
    for (int z = first.z; z <= last.z; ++z) {
      for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
          grid.cells[static_cast<std::size_t>((z * kGrid + y) * kGrid + x)].push_back(kept.size());
        }
      }
    }
    kept.push_back(triangle);
    index.push_back(i);
  }
  return grid;
}

}  // namespace

bool pierced_surface(const ProjectedObject &receiver, const std::vector<glm::vec3> &caster_world,
                     const std::vector<glm::uvec3> &caster_triangles, const glm::vec3 &low,
                     const glm::vec3 &high, float tolerance, PiercedReceiver &pierced) {
  // The two meshes can only meet inside both their bounds.
  glm::vec3 receiver_low(INFINITY), receiver_high(-INFINITY);
  for (const glm::vec3 &p : receiver.world) {
    receiver_low = glm::min(receiver_low, p), receiver_high = glm::max(receiver_high, p);
  }
  const glm::vec3 box_low = glm::max(low, receiver_low) - glm::vec3(tolerance);
  const glm::vec3 box_high = glm::min(high, receiver_high) + glm::vec3(tolerance);
  if (glm::any(glm::lessThan(box_high, box_low))) return false;
  std::vector<Triangle> surface, caster;
  std::vector<std::size_t> surface_index, caster_index;
  TriangleGrid surface_grid = sort_triangles(receiver.world, receiver.object->mesh.triangles,
                                             box_low, box_high, box_low, box_high, surface,
                                             surface_index);
  if (surface.empty()) return false;
  // A crossing point lies on a triangle of each mesh, so only caster triangles whose bounds come
  // near the kept surface triangles' can cross or be crossed (a fighter's feet in the mat, not
  // the whole fighter in the box): those are kept, with a margin well beyond the float rounding
  // of a crossing point (relative to the coordinates' size); the grid stays over the same box.
  glm::vec3 surface_low(INFINITY), surface_high(-INFINITY);
  for (const Triangle &t : surface) {
    surface_low = glm::min(surface_low, t.low), surface_high = glm::max(surface_high, t.high);
  }
  const glm::vec3 size = glm::max(glm::abs(box_low), glm::abs(box_high));
  const float margin = tolerance + 1e-4f * std::max({size.x, size.y, size.z});
  TriangleGrid caster_grid = sort_triangles(
      caster_world, caster_triangles, box_low, box_high, glm::max(box_low, surface_low - margin),
      glm::min(box_high, surface_high + margin), caster, caster_index);
  pierced.caster_crossing.assign(caster_triangles.size(), 0);
  pierced.receiver_crossing.assign(receiver.object->mesh.triangles.size(), 0);
  bool any = false;
  std::vector<ContactPoint> points;  // each crossing point (world) with its pair of triangles
  // The caster's edges through the receiver's triangles, and the receiver's through the caster's.
  auto edges_through = [&](const std::vector<Triangle> &edges, const std::vector<Triangle> &faces,
                           const TriangleGrid &grid, bool edges_are_caster) {
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Triangle &t = edges[e];
      const glm::vec3 *corner[3] = {&t.a, &t.b, &t.c};
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 &p = *corner[k], &q = *corner[(k + 1) % 3];
        grid.each_cell(glm::min(p, q), glm::max(p, q), [&](const std::vector<std::size_t> &cell) {
          for (std::size_t f : cell) {
            if (!crosses(faces[f], p, q, tolerance)) continue;
            pierced.caster_crossing[edges_are_caster ? caster_index[e] : caster_index[f]] = 1;
            pierced.receiver_crossing[surface_index[edges_are_caster ? f : e]] = 1;
            any = true;
            const float dp = glm::dot(faces[f].normal, p - faces[f].a);
            const float dq = glm::dot(faces[f].normal, q - faces[f].a);
            const Triangle &kept_surface = edges_are_caster ? faces[f] : t;
            const Triangle &kept_caster = edges_are_caster ? t : faces[f];
            points.push_back({edges_are_caster ? f : e, edges_are_caster ? e : f,
                              p + (q - p) * (dp / (dp - dq)), kept_surface.normal, kept_caster.normal});
          }
        });
      }
    }
  };
  edges_through(caster, surface, surface_grid, true);
  edges_through(surface, caster, caster_grid, false);
  pierced.contacts = contact_segments(std::move(points));
  pierced.casts = true;  // whatever lies behind, step 1's depth test decides per texel
  return any;
}

}  // namespace gs
