// The depth map's bias for the turn between a caster's facets: a receiver point near the edge
// between two facets of one mesh reads, within the lookup's reach, map texels the other facet
// drew. glPolygonOffset pushes each facet back by its own depth slope, which covers a reading
// point on the same plane; where the surface turns away from the light at the edge (a crest as
// the light sees it), the reading facet falls away faster than the drawing facet's plane, the
// point lies beyond the texel by the difference, and it shadows itself (acne: waves under a low
// light). The edge's corners are drawn pushed away from the light along their own rays by that
// difference, which moves no edge of the map's silhouette (a point slides along the ray the
// light sees it on). Spaces: world; light view (depth along the light's axis) for the texel.
#include "techniques/depth_map/depth_map_facets.h"

#include "techniques/geometry/edge_mesh.h"
#include "techniques/texel_error/texel_footprint.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace gs::depth_map {
namespace {

glm::vec3 unit_normal(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float length = glm::length(n);
  return length > 0.0f ? n / length : glm::vec3(0.0f);
}

}  // namespace

std::vector<glm::vec3> facet_pushed_positions(const WorldMesh &mesh, const LightFrustum &frustum,
                                              const glm::vec3 &light, int side) {
  std::vector<glm::vec3> drawn = mesh.position;
  const EdgeMesh &edges = mesh.surface;
  if (edges.triangles.empty()) return drawn;
  const std::vector<glm::vec3> &world = mesh.surface_world;  // per welded position
  const std::vector<bool> facing = light_facing(edges, world, light);
  const float texel_per_metre = frustum.texel_per_metre(side);
  std::vector<float> push(world.size(), 0.0f);  // metres, along each corner's ray
  for (std::size_t first = 0; first + 1 < edges.edges.size();) {
    std::size_t end = first + 1;
    auto same = [&](const glm::uvec3 &e, const glm::uvec3 &f) {
      return std::minmax(e.x, e.y) == std::minmax(f.x, f.y);
    };
    while (end < edges.edges.size() && same(edges.edges[end], edges.edges[first])) ++end;
    if (end - first != 2) {
      first = end;
      continue;
    }
    const glm::uvec3 edge = edges.edges[first];
    const glm::uint t1 = edge.z, t2 = edges.edges[first + 1].z;
    first = end;
    if (!facing[t1] || !facing[t2]) continue;
    const glm::vec3 &a = world[edge.x], &b = world[edge.y];
    const glm::vec3 middle = 0.5f * (a + b);
    const float depth = -(frustum.view * glm::vec4(middle, 1.0f)).z;
    if (!(depth > 0.0f)) continue;
    const float reach = kFilterReachTexels * texel_per_metre * depth;  // metres across the ray
    const glm::vec3 ray = glm::normalize(middle - light);
    const glm::vec3 along = glm::normalize(b - a);
    // The facet `reading` near the edge reads texels the facet `drawing` drew, within the
    // reach across the ray. Where the surface turns away from the light at the edge, `reading`
    // falls away faster: at its point a reach from the edge (no farther than its far corner)
    // the drawing facet's plane on the light's ray is nearer by `rise` metres, and the edge's
    // corners are pushed back by that (the far corner is not: the reach does not get there).
    for (const auto &[drawing, reading] : {std::pair(t1, t2), std::pair(t2, t1)}) {
      const glm::uvec3 &d = edges.triangles[drawing], &r = edges.triangles[reading];
      const glm::vec3 drawing_normal = unit_normal(world[d.x], world[d.y], world[d.z]);
      const glm::vec3 reading_normal = unit_normal(world[r.x], world[r.y], world[r.z]);
      glm::vec3 inward = glm::cross(reading_normal, along);  // into the reading facet
      const glm::vec3 far_corner = world[r.x] + world[r.y] + world[r.z] - a - b;
      if (glm::dot(inward, far_corner - middle) < 0.0f) inward = -inward;
      const float across = glm::length(inward - glm::dot(inward, ray) * ray);
      const float height = glm::dot(inward, far_corner - middle);  // the facet's own extent
      const glm::vec3 point = middle + inward * std::min(reach / std::max(across, 1e-6f), height);
      const glm::vec3 to_point = point - light;
      const float denominator = glm::dot(drawing_normal, to_point);
      if (!(std::abs(denominator) > 1e-12f)) continue;
      const float s = glm::dot(drawing_normal, a - light) / denominator;
      if (!(s > 0.0f && s < 1.0f)) continue;
      const float rise = (1.0f - s) * glm::length(to_point);
      for (glm::uint corner : {edge.x, edge.y}) push[corner] = std::max(push[corner], rise);
    }
  }
  // Back to the mesh's own vertices, through the position each was welded to.
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const float pushed = push[edges.welded[i]];
    if (!(pushed > 0.0f)) continue;
    const glm::vec3 away = drawn[i] - light;
    const float distance = glm::length(away);
    if (distance > 0.0f) drawn[i] += away / distance * pushed;
  }
  return drawn;
}

}  // namespace gs::depth_map
