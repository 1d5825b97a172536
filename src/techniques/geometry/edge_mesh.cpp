// Casters welded into edge meshes: exactly equal positions made one, every triangle's edges
// sorted so that the uses of one undirected edge lie together, whether the surface is closed,
// which triangles face a point light and where the silhouette runs. Spaces: model (the
// EdgeMesh positions); world (the positions light_facing is given, the light).
#include "techniques/geometry/edge_mesh.h"

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

}  // namespace gs
