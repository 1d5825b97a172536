// The shared technique-test fixture.
#include "technique_fixture.h"

#include "techniques/light_passes/scene_pass.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

void TechniqueTest::SetUp() {
  grGlideInit();
  ASSERT_TRUE(glideShimSetWindowSize(kWidth, kHeight));
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  glideShimClearError();
}

void TechniqueTest::TearDown() { grGlideShutdown(); }

std::vector<FxU16> TechniqueTest::back_buffer() {
  std::vector<FxU16> pixels(kWidth * kHeight);
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, kWidth, kHeight, kWidth * 2, pixels.data());
  return pixels;
}

TechniqueTest::Mask TechniqueTest::white_pixels() {
  Mask set;
  for (FxU16 p : back_buffer()) set.push_back(p != 0);
  return set;
}

TechniqueTest::Mask TechniqueTest::mask_of(gs::ShadowTechnique &technique, const gs::Scene &scene,
                                           gs::FrameReport *report) {
  const gs::FrameReport frame = technique.render(scene, false);
  technique.render_mask(scene);
  if (report != nullptr) *report = frame;
  return white_pixels();
}

TechniqueTest::Mask TechniqueTest::coverage(gs::Scene scene, std::size_t index) {
  scene.lights.clear();
  scene.ambient = glm::vec3(1.0f);
  scene.background = glm::vec3(0.0f);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    scene.objects[i].mesh.set_color(glm::vec3(i == index ? 1.0f : 0.0f));
  }
  gs::render_scene(scene, gs::project_scene(scene));
  return white_pixels();
}

int TechniqueTest::count(const Mask &a) {
  return static_cast<int>(std::count(a.begin(), a.end(), true));
}

int TechniqueTest::count(const Mask &a, const Mask &b) { return count(both(a, b)); }

TechniqueTest::Mask TechniqueTest::both(const Mask &a, const Mask &b) {
  Mask out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] && b[i];
  return out;
}

gs::SceneObject placed_object(const std::string &name, gs::Mesh mesh, const glm::vec3 &at) {
  gs::SceneObject o;
  o.name = name;
  o.mesh = std::move(mesh);
  o.model_to_world = glm::translate(glm::mat4(1.0f), at);
  return o;
}

gs::Scene box_over_floor_scene(int width, int height) {
  gs::Scene scene;
  scene.width = width, scene.height = height;
  scene.objects.push_back(placed_object("floor", gs::make_plane(10.0f, 20), {0, 0, 0}));
  scene.objects[0].casts_shadow = false;
  scene.objects.push_back(placed_object("box", gs::make_box(glm::vec3(0.5f)), {0, 1.5f, 0}));
  gs::SpotLight light;
  light.position = {0, 8, 0};
  light.target = {0, 0, 0};
  scene.lights.push_back(light);
  scene.camera.position = {0, 6, 6};
  scene.camera.target = {0, 0.5f, 0};
  return scene;
}
