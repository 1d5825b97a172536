// scene_file_fuzz: the input's bytes as a scene file for load_scene. The scene's directory also
// holds tetrahedron.obj, so OBJ meshes named by the seed scenes load. Either the load fails with
// a message naming the file and leaves the scene alone, or the scene keeps the documented limits
// (docs/scene_format.md): screen sides, lights, triangles, indices in range, and every point of
// the world within 1e7 m of the origin.
#include "fuzz_files.h"
#include "scene/scene.h"

#include <cmath>
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

// Finite and within the scene's world extent (scene_json.h's kMaxWorldCoordinate), world space.
bool within_world(const glm::vec3 &p) {
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(p[k]) <= 1e7f)) return false;
  return true;
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
    for (const glm::vec3 &model : object.mesh.positions) {
      if (!within_world(glm::vec3(object.model_to_world * glm::vec4(model, 1.0f))))
        violated("a vertex beyond 1e7 m or not finite was accepted");
    }
  }
  if (!within_world(scene.camera.position) || !within_world(scene.camera.target))
    violated("a camera beyond 1e7 m was accepted");
  if (triangles > 2'000'000) violated("more than 2,000,000 triangles were accepted");
  for (const gs::SpotLight &light : scene.lights) {
    if (light.shadow_size < 32 || light.shadow_size > 512) violated("a shadow size is out of range");
    if (!within_world(light.position) || !within_world(light.target))
      violated("a light beyond 1e7 m was accepted");
  }
  return 0;
}
