// The fight: fighters face each other across the ring's centre line (x axis), feet on the mat's
// relief, and the camera circles once every 24 seconds at head height plus a bit.
#include "scene/fight_scene.h"

#include "scene/fighter.h"
#include "scene/ring.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace gs {
namespace {

const glm::vec3 kBodyColors[2] = {{0.75f, 0.12f, 0.1f}, {0.12f, 0.25f, 0.75f}};
constexpr float kStartX = 0.55f;  // each fighter's distance from the centre, metres: in reach
constexpr float kOrbitSeconds = 24.0f;

}  // namespace

FightScene::FightScene(int width, int height, int shadow_size) {
  scene_.width = width;
  scene_.height = height;
  scene_.ambient = glm::vec3(0.28f);
  scene_.background = glm::vec3(0.04f, 0.05f, 0.09f);
  SceneObject ring;
  ring.name = "ring";
  ring.mesh = build_ring();
  ring.casts_shadow = false;  // the posts and ropes would need their own textures; see docs
  scene_.objects.push_back(std::move(ring));
  for (int i = 0; i < 2; ++i) {
    SceneObject fighter;
    fighter.name = i == 0 ? "red fighter" : "blue fighter";
    scene_.objects.push_back(std::move(fighter));
  }
  SpotLight light;
  // Low and behind the red fighter, so its shadow climbs onto the blue one (inter-object
  // shadows were what the article's technique brought to fighting games).
  light.position = {-5.2f, 3.6f, 1.2f};
  light.target = {0.4f, 0.9f, 0.0f};
  light.cone_degrees = 70.0f;
  light.color = glm::vec3(0.95f, 0.92f, 0.85f);
  light.shadow_size = shadow_size;
  scene_.lights.push_back(light);
  scene_.camera.fov_degrees = 50.0f;
  at(0.0f);
}

const Scene &FightScene::at(float time) {
  for (int i = 0; i < 2; ++i) {
    SceneObject &object = scene_.objects[kFighters[i]];
    const FighterPose pose = fight_loop_pose(i, time);
    object.mesh = build_fighter(pose, kBodyColors[i]);
    object.shadow_mesh = build_fighter_lod(pose);
    // Model +z faces the opponent: fighter 0 looks along +x, fighter 1 along -x.
    const float side = i == 0 ? -1.0f : 1.0f;
    const float x = side * kStartX;
    const float facing = i == 0 ? glm::half_pi<float>() : -glm::half_pi<float>();
    const float floor_height = ring_mat_height(x, 0.0f);
    object.model_to_world = glm::rotate(glm::translate(glm::mat4(1.0f), {x, floor_height, 0.0f}),
                                        facing, glm::vec3(0, 1, 0));
  }
  const float angle = glm::two_pi<float>() * time / kOrbitSeconds + 0.6f;
  scene_.camera.position = {6.2f * std::sin(angle), 3.0f, 6.2f * std::cos(angle)};
  scene_.camera.target = {0.0f, 1.55f, 0.0f};
  return scene_;
}

}  // namespace gs
