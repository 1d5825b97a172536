// Triangle meshes and the shapes the scenes are built from. Model space is right-handed, y up,
// metres; triangles wind counter-clockwise seen from outside; colours are linear RGB 0..1.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <string>
#include <vector>

namespace gs {

struct Mesh {
  std::vector<glm::vec3> positions;   // model space
  std::vector<glm::vec3> normals;     // model space, unit length, one per position
  std::vector<glm::vec3> colors;      // one per position, 0..1
  std::vector<glm::uvec3> triangles;  // indices into the arrays above, CCW from outside

  std::size_t triangle_count() const { return triangles.size(); }
  // Appends `other` transformed by `model` (normals by its inverse transpose).
  void append(const Mesh &other, const glm::mat4 &model = glm::mat4(1.0f));
  void set_color(const glm::vec3 &color);  // every vertex
};

// Built-in shapes, centred on the origin unless said otherwise, one colour (white by default).
Mesh make_box(const glm::vec3 &half_extents);
Mesh make_sphere(float radius, int slices, int stacks);
// Along +y from y = 0 to y = length; `caps` closes both ends (a closed mesh).
Mesh make_cylinder(float radius, float length, int slices, bool caps);
// The square [-size/2, size/2]^2 in the xz plane at y = 0, facing +y, divisions^2 quads.
Mesh make_plane(float size, int divisions);
// Like make_plane, lifted by height(x, z); normals from the surface's gradient.
Mesh make_heightfield(float size, int divisions, const std::function<float(float, float)> &height);

// Loads a Wavefront OBJ through tinyobjloader (triangulated; normals computed when absent;
// materials ignored). Files over 256 MiB or 2,000,000 triangles, and paths that are not regular
// files, are refused.
// False, with `error` naming the file and the problem, on failure; `mesh` is left unchanged.
bool load_obj(const std::string &path, Mesh &mesh, std::string &error);

}  // namespace gs
