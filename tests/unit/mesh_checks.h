// Checks on meshes that more than one test file makes: whether a surface is closed and wound
// consistently, how far its normals are from unit length, its bounds (model space, metres).
#pragma once

#include "scene/mesh.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace gs::mesh_checks {

inline const glm::vec3 kRed(0.75f, 0.12f, 0.1f);  // a colour for shapes whose colour is not checked

// Empty when every edge is shared by exactly two triangles that run it in opposite directions
// (a closed, consistently wound surface); otherwise why not. Vertices are welded by position,
// as shapes repeat a position where its normal changes (a box's corners, a cylinder's rims).
inline std::string closed_surface_problem(const Mesh &mesh) {
  std::map<std::tuple<float, float, float>, unsigned> welded_id;
  std::vector<unsigned> id_of(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 &p = mesh.positions[i];
    id_of[i] = welded_id.try_emplace({p.x, p.y, p.z}, static_cast<unsigned>(welded_id.size()))
                   .first->second;
  }
  std::map<std::pair<unsigned, unsigned>, int> directed_edges;
  for (const glm::uvec3 &triangle : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const unsigned from = id_of[triangle[k]], to = id_of[triangle[(k + 1) % 3]];
      if (from == to) return "a triangle with two corners at one position";
      ++directed_edges[{from, to}];
    }
  }
  for (const auto &[edge, count] : directed_edges) {
    if (count != 1) return "an edge run the same way by " + std::to_string(count) + " triangles";
    if (directed_edges.count({edge.second, edge.first}) == 0) return "an open edge";
  }
  return "";
}

inline float worst_normal_length_error(const Mesh &mesh) {
  float worst = 0.0f;
  for (const glm::vec3 &n : mesh.normals) worst = std::max(worst, std::abs(glm::length(n) - 1.0f));
  return worst;
}

struct Bounds {
  glm::vec3 low{std::numeric_limits<float>::max()};
  glm::vec3 high{std::numeric_limits<float>::lowest()};
};

inline Bounds bounds_of(const Mesh &mesh) {
  Bounds bounds;
  for (const glm::vec3 &p : mesh.positions) {
    bounds.low = glm::min(bounds.low, p);
    bounds.high = glm::max(bounds.high, p);
  }
  return bounds;
}

}  // namespace gs::mesh_checks
