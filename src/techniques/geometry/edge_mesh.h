// A caster's surface as silhouettes and shadow volumes need it: welded by position, its edges
// paired up, closed or not. The stencil-volume technique extrudes its silhouettes; the projected,
// planar and depth-map techniques ask whether a caster is closed and where its silhouette runs.
#pragma once

#include "scene/mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace gs {

// A caster welded by position into one surface, which is what silhouettes and caps need: a
// mesh's corners are often split for flat normals (a box's faces) or seams.
struct EdgeMesh {
  std::vector<glm::vec3> positions;   // model space, each distinct position once
  std::vector<glm::uint> welded;      // per vertex of the mesh: its position's index in `positions`
  std::vector<glm::uvec3> triangles;  // into `positions`, CCW from outside, three distinct corners
                                      // not on one line
  // Every triangle's three edges (from, to, triangle), sorted so that the uses of one undirected
  // edge are adjacent.
  std::vector<glm::uvec3> edges;
  // Every edge is walked as often one way as the other (so the surface encloses a volume). Two
  // parts touching at an edge still count as closed.
  bool closed = false;
};

// Welds `mesh` (exactly equal positions) and builds its edges; not closed for an open surface,
// a non-finite position or an index out of range.
EdgeMesh build_edge_mesh(const Mesh &mesh);
// build_edge_mesh(mesh).closed without building the edges (cheaper: the projected and planar
// techniques ask it of every caster every frame, and a fighter's mesh is new every frame).
bool is_closed_surface(const Mesh &mesh);

// Per triangle of `mesh`: whether it faces the point light at `light` (world), with `world` the
// mesh's positions in world space (one per EdgeMesh position).
std::vector<bool> light_facing(const EdgeMesh &mesh, const std::vector<glm::vec3> &world,
                               const glm::vec3 &light);

// An edge between a light-facing and a back-facing triangle, in the direction the light-facing
// one walks it (indices into EdgeMesh::positions). An edge where two parts meet may appear twice.
struct SilhouetteEdge {
  glm::uint from = 0, to = 0;
};
std::vector<SilhouetteEdge> find_silhouette(const EdgeMesh &mesh, const std::vector<bool> &facing);

}  // namespace gs
