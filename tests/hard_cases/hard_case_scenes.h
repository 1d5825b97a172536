// The hard cases' scenes as the tests (tests/numeric/hard_cases_test.cpp) and the sweeps
// (bench/hard_case_sweeps.cpp) both use them: the scene files of this folder, and the parameters
// the cases vary (a receiver's tilt, the whole scene's place and size).
#pragma once

#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace hard_cases {

#ifndef GLIDESHADOWS_HARD_CASES_DIR
#error "GLIDESHADOWS_HARD_CASES_DIR must name tests/hard_cases"
#endif

// A scene file of this folder; throws with the loader's message (a missing or broken file is a
// bug of the test data, not a case).
inline gs::Scene load(const std::string &name) {
  gs::Scene scene;
  std::string error;
  if (!gs::load_scene(std::string(GLIDESHADOWS_HARD_CASES_DIR) + "/" + name, scene, error)) {
    throw std::runtime_error(error);
  }
  return scene;
}

// The whole scene mapped by p -> offset + scale * p (world space): objects, lights, camera and
// its clip distances, so the picture stays the same. Computed in double, so the only rounding is
// the float the scene stores (at 1e6 m a float's step is 1/16 m: the offsets used are whole
// metres, and every position of the scene files is a multiple of 1/16 m).
inline void move_scene(gs::Scene &scene, const glm::dvec3 &offset, double scale) {
  const glm::dmat4 to_new = glm::scale(glm::translate(glm::dmat4(1.0), offset), glm::dvec3(scale));
  auto point = [&](const glm::vec3 &p) {
    return glm::vec3(glm::dvec3(to_new * glm::dvec4(glm::dvec3(p), 1.0)));
  };
  for (gs::SceneObject &object : scene.objects) {
    object.model_to_world = glm::mat4(to_new * glm::dmat4(object.model_to_world));
  }
  for (gs::SpotLight &light : scene.lights) {
    light.position = point(light.position);
    light.target = point(light.target);
  }
  scene.camera.position = point(scene.camera.position);
  scene.camera.target = point(scene.camera.target);
  scene.camera.near_plane = static_cast<float>(scene.camera.near_plane * scale);
  scene.camera.far_plane = static_cast<float>(scene.camera.far_plane * scale);
}

// grazing_plane.json with its light turned `degrees` from the plane's normal towards +x, on a
// circle of 8 m about the plane's centre, still aimed at that centre.
inline gs::Scene grazing_plane(float degrees) {
  gs::Scene scene = load("grazing_plane.json");
  const float angle = glm::radians(degrees);
  scene.lights[0].position = glm::vec3(std::sin(angle), std::cos(angle), 0.0f) * 8.0f;
  return scene;
}

// waves_low_sun.json with its light `elevation_degrees` above the ground (9 m from the waves'
// centre, from the file's side) and the waves' height scaled to `amplitude` metres (the file's
// is 0.6): a curved receiver shadowing itself, for the depth map's bias.
inline gs::Scene waves_low_sun(float elevation_degrees, float amplitude) {
  gs::Scene scene = load("waves_low_sun.json");
  const float angle = glm::radians(elevation_degrees);
  scene.lights[0].position = glm::vec3(-9.0f * std::cos(angle), 9.0f * std::sin(angle), 1.0f);
  scene.objects[0].model_to_world =
      glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, amplitude / 0.6f, 1.0f));
  return scene;
}

}  // namespace hard_cases
