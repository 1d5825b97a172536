// obj_fuzz: the input's bytes as an OBJ file for load_obj (tinyobjloader). Either the load fails
// with a message naming the file and leaves the mesh alone, or it returns a mesh whose every
// index is in range and whose normals are finite unit vectors.
#include "fuzz_files.h"
#include "scene/mesh.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

[[noreturn]] void violated(const char *what) {
  std::fprintf(stderr, "obj_fuzz: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::string path = fuzz_files::write("mesh.obj", data, size);
  gs::Mesh mesh = gs::make_box(glm::vec3(1.0f));  // a sentinel a failed load must not touch
  const std::size_t sentinel_triangles = mesh.triangle_count();
  std::string error;
  if (!gs::load_obj(path, mesh, error)) {
    if (error.rfind(path + ": ", 0) != 0 || error.size() <= path.size() + 2)
      violated("the error does not name the file and the problem");
    if (mesh.triangle_count() != sentinel_triangles) violated("a failed load changed the mesh");
    return 0;
  }
  if (mesh.triangles.empty()) violated("a mesh without triangles was accepted");
  const std::size_t vertices = mesh.positions.size();
  if (mesh.normals.size() != vertices || mesh.colors.size() != vertices)
    violated("normals or colours do not match the positions");
  for (const glm::uvec3 &triangle : mesh.triangles) {
    for (int k = 0; k < 3; ++k)
      if (triangle[k] >= vertices) violated("a triangle index is out of range");
  }
  for (const glm::vec3 &normal : mesh.normals) {
    const float length = glm::length(normal);
    if (!std::isfinite(length) || std::fabs(length - 1.0f) > 1e-3f) violated("a normal is not unit length");
  }
  return 0;
}
