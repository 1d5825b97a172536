// Stencil shadow volumes, the geometry: casters welded into edge meshes, their light-facing
// triangles and silhouettes, the volumes extruded from them, and the test that picks z-fail.
// Spaces: model (EdgeMesh positions); world (the light, the casters' world positions, the bounding
// spheres); homogeneous world relative to the camera's position, w = 0 at infinity (the volumes).
#include "techniques/stencil_volume_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

namespace gs {
namespace {

std::pair<glm::uint, glm::uint> undirected(const glm::uvec3 &edge) {
  return {std::min(edge.x, edge.y), std::max(edge.x, edge.y)};
}

// The end of the run of `edges` (sorted by undirected edge) that starts at `first`.
std::size_t end_of_edge(const std::vector<glm::uvec3> &edges, std::size_t first) {
  std::size_t end = first + 1;
  while (end < edges.size() && undirected(edges[end]) == undirected(edges[first])) ++end;
  return end;
}

// Whether `probe` may touch the shadow volume that `caster` casts from a point light at `light`.
// Every point of the volume lies on a ray from the light through a caster point, beyond it: in
// the cone around the sphere, no nearer the light than the sphere's nearest point.
bool may_touch_volume(const glm::vec3 &light, const Sphere &caster, const Sphere &probe) {
  const glm::vec3 to_caster = caster.centre - light, to_probe = probe.centre - light;
  const float caster_distance = glm::length(to_caster), probe_distance = glm::length(to_probe);
  if (caster_distance <= caster.radius || probe_distance <= probe.radius) return true;
  if (probe_distance + probe.radius < caster_distance - caster.radius) return false;
  const float cone = std::asin(caster.radius / caster_distance);
  const float spread = std::asin(probe.radius / probe_distance);
  const float angle = std::acos(std::clamp(
      glm::dot(to_caster, to_probe) / (caster_distance * probe_distance), -1.0f, 1.0f));
  return angle <= cone + spread + 1e-4f;  // a margin for the rounding of acos near the edge
}

// Welds `mesh` by exactly equal positions into `positions` (each distinct one once) and
// `triangles` (corners among them), leaving out triangles with two corners welded together or
// three on one line: they have no area, bound nothing, and their edges would make a closed
// surface look open; `welded` gets each mesh vertex's index into `positions`. False, with all
// three empty, for a non-finite position or an index out of range.
bool weld(const Mesh &mesh, std::vector<glm::vec3> &positions, std::vector<glm::uvec3> &triangles,
          std::vector<glm::uint> &welded) {
  positions.clear();
  triangles.clear();
  welded.clear();
  const std::size_t n = mesh.positions.size();
  for (const glm::vec3 &p : mesh.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  }
  std::vector<glm::uint> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](glm::uint a, glm::uint b) {
    const glm::vec3 &p = mesh.positions[a], &q = mesh.positions[b];
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  });
  welded.resize(n);
  for (glm::uint i : order) {
    if (positions.empty() || positions.back() != mesh.positions[i]) {
      positions.push_back(mesh.positions[i]);
    }
    welded[i] = static_cast<glm::uint>(positions.size() - 1);
  }
  for (const glm::uvec3 &t : mesh.triangles) {
    if (t.x >= n || t.y >= n || t.z >= n) {
      positions.clear();
      triangles.clear();
      welded.clear();
      return false;
    }
    const glm::uvec3 w(welded[t.x], welded[t.y], welded[t.z]);
    if (w.x == w.y || w.y == w.z || w.z == w.x) continue;
    const glm::vec3 &a = positions[w.x], &b = positions[w.y], &c = positions[w.z];
    if (glm::cross(b - a, c - a) == glm::vec3(0.0f)) continue;
    triangles.push_back(w);
  }
  return true;
}

}  // namespace

EdgeMesh build_edge_mesh(const Mesh &mesh) {
  EdgeMesh result;
  if (!weld(mesh, result.positions, result.triangles, result.welded)) return result;
  for (glm::uint index = 0; index < result.triangles.size(); ++index) {
    const glm::uvec3 &w = result.triangles[index];
    for (const glm::uvec3 &edge : {glm::uvec3(w.x, w.y, index), glm::uvec3(w.y, w.z, index),
                                   glm::uvec3(w.z, w.x, index)}) {
      result.edges.push_back(edge);
    }
  }
  std::sort(result.edges.begin(), result.edges.end(),
            [](const glm::uvec3 &a, const glm::uvec3 &b) { return undirected(a) < undirected(b); });
  result.closed = true;
  for (std::size_t first = 0, end = 0; first < result.edges.size(); first = end) {
    end = end_of_edge(result.edges, first);
    int balance = 0;  // walks low -> high minus walks high -> low
    for (std::size_t k = first; k < end; ++k) {
      balance += result.edges[k].x < result.edges[k].y ? 1 : -1;
    }
    if (balance != 0) result.closed = false;
  }
  return result;
}

bool is_closed_surface(const Mesh &mesh) {
  std::vector<glm::vec3> positions;
  std::vector<glm::uvec3> triangles;
  std::vector<glm::uint> welded;
  if (!weld(mesh, positions, triangles, welded)) return false;
  // Every walk of an undirected edge {low, high} filed under its low corner (a counting sort),
  // as high << 1 plus 1 when it goes low -> high; each corner's few walks are then sorted by
  // high, and build_edge_mesh's balance (walks up minus walks down) summed per edge.
  std::vector<std::size_t> first(positions.size() + 1, 0);
  for (const glm::uvec3 &t : triangles) {
    ++first[std::min(t.x, t.y) + 1];
    ++first[std::min(t.y, t.z) + 1];
    ++first[std::min(t.z, t.x) + 1];
  }
  for (std::size_t v = 0; v < positions.size(); ++v) first[v + 1] += first[v];
  std::vector<std::uint64_t> walks(first.back());
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (const glm::uvec3 &t : triangles) {
    for (const auto &[from, to] : {std::pair(t.x, t.y), std::pair(t.y, t.z), std::pair(t.z, t.x)}) {
      const std::uint64_t high = std::max(from, to);
      walks[next[std::min(from, to)]++] = high << 1 | (from < to ? 1u : 0u);
    }
  }
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const auto begin = walks.begin() + static_cast<std::ptrdiff_t>(first[v]);
    const auto end = walks.begin() + static_cast<std::ptrdiff_t>(first[v + 1]);
    std::sort(begin, end);
    for (auto run = begin; run != end;) {
      int balance = 0;
      const std::uint64_t high = *run >> 1;
      for (; run != end && *run >> 1 == high; ++run) balance += (*run & 1u) != 0 ? 1 : -1;
      if (balance != 0) return false;
    }
  }
  return true;
}

std::vector<bool> light_facing(const EdgeMesh &mesh, const std::vector<glm::vec3> &world,
                               const glm::vec3 &light) {
  std::vector<bool> facing(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const glm::vec3 &a = world[mesh.triangles[t].x], &b = world[mesh.triangles[t].y],
                    &c = world[mesh.triangles[t].z];
    facing[t] = glm::dot(glm::cross(b - a, c - a), light - a) > 0.0f;  // edge-on counts as away
  }
  return facing;
}

std::vector<SilhouetteEdge> find_silhouette(const EdgeMesh &mesh, const std::vector<bool> &facing) {
  std::vector<SilhouetteEdge> silhouette;
  // Per undirected edge, the light-facing walks low -> high minus those high -> low: 0 where both
  // sides face the same way; where several parts meet at one edge, each unmatched walk counts.
  for (std::size_t first = 0, end = 0; first < mesh.edges.size(); first = end) {
    end = end_of_edge(mesh.edges, first);
    const auto [low, high] = undirected(mesh.edges[first]);
    int walks = 0;
    for (std::size_t k = first; k < end; ++k) {
      if (facing[mesh.edges[k].z]) walks += mesh.edges[k].x < mesh.edges[k].y ? 1 : -1;
    }
    for (; walks > 0; --walks) silhouette.push_back({low, high});
    for (; walks < 0; ++walks) silhouette.push_back({high, low});
  }
  return silhouette;
}

namespace stencil_volume {

void build_volumes(const std::vector<Caster> &casters, const glm::vec3 &light,
                   const glm::vec3 &origin, bool caps, std::vector<glm::vec4> &out) {
  out.clear();
  for (const Caster &caster : casters) {
    const std::vector<bool> facing = light_facing(caster.mesh, caster.world, light);
    const auto on = [&](glm::uint i) { return glm::vec4(caster.world[i] - origin, 1.0f); };
    const auto beyond = [&](glm::uint i) { return glm::vec4(caster.world[i] - light, 0.0f); };
    for (const SilhouetteEdge &e : find_silhouette(caster.mesh, facing)) {
      // The side walks the edge against the light-facing triangle, as its neighbour on the
      // volume's surface must for both to face outward.
      out.insert(out.end(), {on(e.to), on(e.from), beyond(e.from),
                             on(e.to), beyond(e.from), beyond(e.to)});
    }
    if (!caps) continue;
    // Both caps are the triangles facing away from the light: the near cap where they are,
    // turned round to face the light, the far cap sent to infinity. Their rims are the
    // silhouette, so the volume is closed, and it holds what lies behind the caster's dark side.
    // (The light-facing triangles would close it as well, but they lie on the caster's lit
    // surface, and wherever the drawn surface is not exactly that mesh - a simplified
    // shadow_mesh, or depths rounded differently - the lit surface would land inside its own
    // volume and be counted in shadow. The dark side is never lit, whatever the count says.)
    for (std::size_t t = 0; t < caster.mesh.triangles.size(); ++t) {
      if (facing[t]) continue;
      const glm::uvec3 &c = caster.mesh.triangles[t];
      out.insert(out.end(), {on(c.x), on(c.z), on(c.y), beyond(c.x), beyond(c.y), beyond(c.z)});
    }
  }
}

}  // namespace stencil_volume

bool near_plane_may_be_in_shadow(const Scene &scene, const SpotLight &light) {
  const Camera &camera = scene.camera;
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const float half_height = camera.near_plane * std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  const float half_width =
      half_height * static_cast<float>(scene.width) / static_cast<float>(scene.height);
  // A sphere around the near-plane rectangle, large enough to hold the camera position too.
  const Sphere near_plane{camera.position + forward * camera.near_plane,
                          std::sqrt(camera.near_plane * camera.near_plane +
                                    half_width * half_width + half_height * half_height)};
  for (const SceneObject &object : scene.objects) {
    if (!object.casts_shadow || caster_mesh(object).triangles.empty()) continue;
    if (may_touch_volume(light.position, caster_bounds(object), near_plane)) return true;
  }
  return false;
}

}  // namespace gs
