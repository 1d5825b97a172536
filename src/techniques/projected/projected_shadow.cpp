// The projected shadow texture in the article's order: the frame that runs all five steps
// (render_projected_shadows). Steps 1 to 3 go a caster and a light at a time
// (caster_shadow.cpp): step 1's light view is fitted in light_view_fit.cpp and its flat render
// is caster_from_light.cpp, step 2 is shadow_textures.cpp (with the textures' TMU memory,
// shadow_texture_memory.h), step 3 receiver_coords.cpp; step 4 is scene_pass.cpp, step 5 and
// the shadow mask shadow_pass.cpp. Spaces: light view and light clip (step 1); Glide screen
// (pixels, y down) for the light's size x size view in step 1 and the camera in steps 4-5.
#include "techniques/projected/projected_shadow.h"
#include "techniques/projected/projected_frame.h"
#include "techniques/step_clock.h"

#include "techniques/light_passes/slide_projector.h"

#include <glide_shim.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace gs {
namespace {

using Clock = std::chrono::steady_clock;

// The scene pass drew over the slide textures' TMU memory: `memory` no longer holds what lay
// there.
void forget_slide_textures(const Scene &scene, ShadowTextureMemory &memory) {
  if (needs_projective_passes(scene)) {
    memory.forget(kProjectiveTextureAddress, kProjectiveTextureAddress + kProjectiveTextureBytes);
  }
}

// Step 4: the scene, which the renderer draws while the program sets up step 5's passes.
void render_scene_step(ProjectedFrame &frame, ShadowTextureMemory &memory) {
  const auto start = Clock::now();
  render_scene(frame.scene, frame.geometry);
  forget_slide_textures(frame.scene, memory);
  if (!frame.result.jobs.empty()) glideShimFlush();  // shadow_pass.cpp
  frame.finish_step(3, start);
}

// Step 5, a light at a time (jobs are in light order). Between lights the depth buffer gets step
// 4's surfaces back (a depth-only scene pass), so each light's marks start from them.
void render_shadow_passes(ProjectedFrame &frame, ShadowTextureMemory &memory) {
  const auto start = Clock::now();
  const Scene &scene = frame.scene;
  ShadowFrame &result = frame.result;
  const BindShadowTexture bind = [&](const ShadowJob &job) {
    std::optional<FxU32> address = bind_shadow_texture(job, memory, frame.geometry);
    if (!address) {
      result.errors.push_back("'" + scene.objects[job.caster].name + "' casts no shadow from light " +
                              std::to_string(job.light) + ": step 1 cannot draw its texture again: " +
                              glideShimGetLastErrorMessage());
    }
    return address;
  };
  std::vector<const ShadowJob *> same_light;
  for (std::size_t j = 0; j < result.jobs.size(); ++j) {
    same_light.push_back(&result.jobs[j]);
    if (j + 1 < result.jobs.size() && result.jobs[j + 1].light == result.jobs[j].light) continue;
    render_light_shadow_passes(same_light, frame.options, bind);
    same_light.clear();
    if (j + 1 < result.jobs.size()) {
      grColorMask(FXFALSE, FXFALSE);
      render_scene(scene, frame.geometry);
      forget_slide_textures(scene, memory);
      grColorMask(FXTRUE, FXFALSE);
    }
  }
  result.textures_loaded = memory.loads() > 0;
  frame.finish_step(4, start);
}

}  // namespace

ProjectedFrame::ProjectedFrame(const Scene &scene_in, const ProjectedShadowOptions &options_in,
                               bool synchronous_in)
    : scene(scene_in), options(options_in), synchronous(synchronous_in), start(Clock::now()),
      geometry(project_scene(scene_in)) {
  grRenderBuffer(GR_BUFFER_BACKBUFFER);
  // TMU0 memory from its lowest texture address to its end (grTexMaxAddress leaves 8 bytes).
  result.textures = ShadowTextureMemory(grTexMinAddress(GR_TMU0), grTexMaxAddress(GR_TMU0) + 8);
  const bool point_sampled = options.chroma_key || !options.bilinear;
  largest_footprint = options.largest_texel_footprint_px > 0.0f ? options.largest_texel_footprint_px
                      : point_sampled                           ? kLargestPointSampledFootprintPx
                                                                : kLargestTexelFootprintPx;
  if (std::isinf(options.largest_texel_footprint_px)) largest_edge_error = INFINITY;
}

void ProjectedFrame::finish_step(int step, Clock::time_point step_start) {
  if (synchronous) grSstIdle();
  result.times.ms[step] += elapsed_ms(step_start);
}

void ProjectedFrame::read_pending() {
  if (!pending) return;
  const std::size_t id = pending->id;
  auto has_id = [id](const ShadowJob &job) { return job.texture.id == id; };
  ShadowJob *job = nullptr;
  for (std::vector<ShadowJob> *jobs : {&result.jobs, &caster_jobs}) {
    const auto found = std::find_if(jobs->begin(), jobs->end(), has_id);
    if (!job && found != jobs->end()) job = &*found;
  }
  if (job) {
    const auto step_start = Clock::now();
    job->texture = pending->placed ? make_shadow_texture(job->view, options, *pending->placed)  // 2
                                   : read_shadow_texture(job->view, options);
    job->texture.id = id;
    finish_step(1, step_start);
  }
  pending.reset();
}

void ProjectedFrame::add_note(const LightView &view) {
  if (!view.note.empty() &&
      std::find(result.warnings.begin(), result.warnings.end(), view.note) == result.warnings.end()) {
    result.warnings.push_back(view.note);
  }
}

ShadowFrame render_projected_shadows(const Scene &scene, const ProjectedShadowOptions &options,
                                     bool synchronous) {
  ProjectedFrame frame(scene, options, synchronous);
  for (std::size_t light = 0; light < scene.lights.size(); ++light) {
    if (scene.lights[light].is_projector()) continue;  // slides cast no shadows
    for (std::size_t caster = 0; caster < scene.objects.size(); ++caster) {
      if (scene.objects[caster].casts_shadow) cast_caster_shadow(frame, light, caster);  // 1 to 3
    }
  }
  // What TMU memory holds as step 5 goes: step 2's textures, but for the slide textures' memory
  // after each scene pass, and what step 5 loads.
  ShadowTextureMemory memory = frame.result.textures;
  frame.read_pending();  // 2, the last texture's
  render_scene_step(frame, memory);     // 4
  render_shadow_passes(frame, memory);  // 5
  ShadowFrame result = std::move(frame.result);
  result.times.total_ms = elapsed_ms(frame.start);
  result.geometry = std::move(frame.geometry);
  // Errors are warnings too, so that a caller showing only warnings still shows them.
  result.warnings.insert(result.warnings.begin(), result.errors.begin(), result.errors.end());
  return result;
}

}  // namespace gs
