// The pieces Nguyen's figures share (nguyen_steps.h), drawn by the projected shadow's own steps.
// Spaces: world; the light's 256 x 256 view (pixels = texels of the shadow texture, y down).
#include "figures/nguyen_steps.h"

#include "measure/ground_truth.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide_shim.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace gs::figures {

Steps run_steps(const Scene &scene, const ProjectedShadowOptions &options,
                const glm::mat4 &narrowing, FigureFault fault) {
  Steps steps;
  ShadowJob job;
  job.caster = kFighter;
  job.light = 0;
  job.view = fit_light_view(scene, kFighter, 0, options);
  if (!job.view.usable) return steps;
  job.view.projection = narrowing * job.view.projection;
  const FxU32 address = grTexMinAddress(GR_TMU0);
  grRenderBuffer(GR_BUFFER_BACKBUFFER);
  render_caster_from_light(scene, kFighter, job.view, options, address);  // 1
  if (!job.view.usable) return steps;
  steps.light_words = figures::read_back(job.view.size, job.view.size);
  job.texture = make_shadow_texture(job.view, options, address);  // 2
  if (fault == FigureFault::ShiftedProjection) {
    // Light clip space: 6 texels of the 256 (clip x spans 2 over the texture).
    job.view.projection = glm::translate(glm::mat4(1.0f), glm::vec3(12.0f / 256.0f, 0.0f, 0.0f)) *
                          job.view.projection;
  }
  const FrameGeometry geometry = project_scene(scene);
  job.receivers = compute_receiver_coords(scene, geometry, kFighter, scene.lights[0], job.view,
                                          options);  // 3
  render_scene(scene, geometry);                     // 4
  if (fault == FigureFault::StaleReadBack) steps.light_words = figures::read_back(job.view.size, job.view.size);
  if (fault != FigureFault::ShadowLeftOut) {
    render_shadow_pass(job, options);  // 5
    steps.frame.jobs.push_back(std::move(job));
  }
  steps.usable = true;
  return steps;
}

glm::mat4 border_cutting_view() {
  return glm::translate(glm::mat4(1.0f), glm::vec3(-0.7f, 0.0f, 0.0f)) *
         glm::scale(glm::mat4(1.0f), glm::vec3(1.3f, 1.3f, 1.0f));
}

// The light's view of the fighter as a camera: the same eye, axis, up and field of view as
// step 1, so its 256 x 256 pixels are the shadow texture's texels.
Scene from_the_light(const Scene &scene) {
  ProjectedShadowOptions options;
  const LightView view = fit_light_view(scene, kFighter, 0, options);
  const float fov = glm::degrees(2.0f * std::atan(1.0f / view.projection[1][1]));
  return figures::seen_from(scene, scene.lights[0].position, caster_bounds(scene.objects[kFighter]).centre,
                            fov, view.size);
}

// The shadow texture's alpha nibble as a picture: white 1111b, black 0000b, magenta between.
FigureImage alpha_picture(const Words &words) {
  FigureImage image = figures::filled(words.width, words.height, 0, 0, 0);
  for (std::size_t i = 0; i < words.data.size(); ++i) {
    const unsigned alpha = words.data[i] >> 12;
    const bool between = alpha != 0 && alpha != 15;
    image.rgb[3 * i] = static_cast<std::uint8_t>(alpha == 15 || between ? 255 : 0);
    image.rgb[3 * i + 1] = static_cast<std::uint8_t>(alpha == 15 ? 255 : 0);
    image.rgb[3 * i + 2] = static_cast<std::uint8_t>(alpha == 15 || between ? 255 : 0);
  }
  return image;
}

Mask alpha_set(const Words &words) {
  Mask mask(words.data.size());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = (words.data[i] >> 12) == 15;
  return mask;
}

// Texels of `mask` (size x size) within `ring` texels of the texture's edge.
long near_border(const Mask &mask, int size, int ring) {
  long n = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const bool edge = x < ring || y < ring || x >= size - ring || y >= size - ring;
      n += edge && mask[static_cast<std::size_t>(y * size + x)] != 0;
    }
  }
  return n;
}

// The ray-cast shadow of the mesh step 1 drew (the fighter's simplified shadow mesh) on the
// floor and the step, and which pixels count: floor and step pixels outside the step's own
// shadow (the ray caster lets every object cast; the figures leave the step's shadow out).
bool true_shadow(Scene scene, Mask &shadow, Mask &receivers) {
  scene.objects[kFighter].mesh = caster_mesh(scene.objects[kFighter]);
  Scene without_fighter = scene;
  without_fighter.objects.pop_back();
  GroundTruth truth, step_only;
  std::string error;
  if (!compute_ground_truth(scene, truth, error) || !compute_ground_truth(without_fighter, step_only, error)) {
    return false;
  }
  receivers.assign(truth.object.size(), 0);
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    const bool floor_or_step = truth.object[i] == static_cast<int>(kFloor) || truth.object[i] == static_cast<int>(kStep);
    receivers[i] = floor_or_step && step_only.shadow[i] == 0;
  }
  shadow = truth.shadow;
  return true;
}

MaskErrors against_truth(const Scene &scene, const Words &mask) {
  Mask shadow, receivers;
  if (!true_shadow(scene, shadow, receivers)) return {};
  return compare_masks(figures::non_zero(mask), shadow, receivers, scene.width, scene.height);
}

}  // namespace gs::figures
