// scene_file_fuzz: the input's bytes as a scene file for load_scene. The scene's directory also
// holds tetrahedron.obj, so OBJ meshes named by the seed scenes load. Either the load fails with
// a message naming the file and leaves the scene alone, or the scene keeps the documented limits
// (docs/scene_format.md): screen sides, lights, triangles, and indices in range.
#include "fuzz_files.h"
#include "scene/scene.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

[[noreturn]] void violated(const char *what) {
  std::fprintf(stderr, "scene_file_fuzz: %s\n", what);
  std::abort();
}

constexpr char kTetrahedron[] =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

void check_mesh(const gs::Mesh &mesh) {
  const std::size_t vertices = mesh.positions.size();
  if (mesh.normals.size() != vertices || mesh.colors.size() != vertices)
    violated("normals or colours do not match the positions");
  for (const glm::uvec3 &triangle : mesh.triangles) {
    for (int k = 0; k < 3; ++k)
      if (triangle[k] >= vertices) violated("a triangle index is out of range");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  static const bool obj_written = [] {
    fuzz_files::write("tetrahedron.obj", reinterpret_cast<const std::uint8_t *>(kTetrahedron),
                      std::strlen(kTetrahedron));
    return true;
  }();
  (void)obj_written;
  const std::string path = fuzz_files::write("scene.json", data, size);
  gs::Scene scene;
  scene.width = 7;  // a sentinel a failed load must not touch
  std::string error;
  if (!gs::load_scene(path, scene, error)) {
    if (error.rfind(path + ": ", 0) != 0 || error.size() <= path.size() + 2)
      violated("the error does not name the file and the problem");
    if (scene.width != 7 || !scene.objects.empty()) violated("a failed load changed the scene");
    return 0;
  }
  if (scene.width < 1 || scene.width > 2048 || scene.height < 1 || scene.height > 2048)
    violated("the screen is beyond 1..2048");
  if (scene.objects.empty()) violated("a scene without objects was accepted");
  if (scene.lights.size() > 16) violated("more than 16 lights were accepted");
  std::size_t triangles = 0;
  for (const gs::SceneObject &object : scene.objects) {
    check_mesh(object.mesh);
    check_mesh(object.shadow_mesh);
    triangles += object.mesh.triangle_count() + object.shadow_mesh.triangle_count();
  }
  if (triangles > 2'000'000) violated("more than 2,000,000 triangles were accepted");
  for (const gs::SpotLight &light : scene.lights) {
    if (light.shadow_size < 32 || light.shadow_size > 512) violated("a shadow size is out of range");
  }
  return 0;
}
