// What render_projected_shadows (projected_shadow.cpp) keeps over a frame while it goes through
// the article's steps, and its steps 1 to 3 for one caster under one light (caster_shadow.cpp):
// every texture of the caster's shadow drawn, read back and given its receivers, then checked
// against the screen (texel_footprint.h, shadow_edge_error.h) and kept or refused.
#pragma once

#include "techniques/projected/projected_shadow.h"

#include <glide.h>

#include <chrono>
#include <cstddef>
#include <optional>
#include <vector>

namespace gs {

struct ProjectedFrame {
  ProjectedFrame(const Scene &scene, const ProjectedShadowOptions &options, bool synchronous);

  const Scene &scene;
  const ProjectedShadowOptions &options;
  const bool synchronous;  // each step ends with grSstIdle, so its time includes its rendering
  const std::chrono::steady_clock::time_point start;
  ShadowFrame result;
  FrameGeometry geometry;  // step 4's projection of the scene (result.geometry at the end)
  std::size_t texture_ids = 0;  // the next texture's ShadowTexture::id
  // The most screen pixels a texel may span where a shadow's edge can fall (texel_footprint.h):
  // the options', or the measured default for the filter.
  float largest_footprint = 0.0f;
  // The most pixels the estimated error along the frame's shadow edges may reach
  // (shadow_edge_error.h), from the receivers' pixels once a shadow has an estimate; off with
  // the footprint check.
  std::optional<float> largest_edge_error;
  bool edge_error_asked = false;  // a shadow has had an estimate (or lost centres)
  // A lower bound of largest_edge_error (screen pixels), enough to accept the shadows so far
  // (screen_check.h).
  std::optional<float> edge_error_at_least;
  float edge_error_taken = 0.0f;  // by the shadows cast so far
  // Every shadow's so far, cast or refused, at each doubling of its size: a refusal names a
  // larger size only where its error fits beside them all, since they may all be cast there.
  EdgeErrorEstimate edge_error_of_all;
  // Step 2 of the texture step 1 drew last on the LFB path, whose drawing the renderer was left
  // to do (glideShimFlush) while the program goes on with the next texture's steps 1 and 3 and
  // the next caster's fitting: the read-back then waits only for what is left of it. Done before
  // anything else draws (the next step 1, which clears the same corner of the back buffer, and
  // step 4). A texture of a caster refused meanwhile is read only while its jobs are still at
  // hand (no other caster has begun since), and then for nothing: no pass draws with it.
  struct PendingRead {
    std::size_t id;               // the texture's (ShadowTexture::id)
    std::optional<FxU32> placed;  // its TMU address, when step 2 placed it
  };
  std::optional<PendingRead> pending;
  std::vector<ShadowJob> caster_jobs;  // the textures of the caster being cast

  // Adds the time since `start` to step `step` (0..4), after grSstIdle when synchronous.
  void finish_step(int step, std::chrono::steady_clock::time_point step_start);
  void read_pending();  // step 2 of the pending texture, if any
  void add_note(const LightView &view);  // the view's note among the warnings, once a frame
};

// Steps 1 to 3 (with step 2's read-back, or its wait in `pending`) for `caster`'s shadow from
// `light`: into frame.result.jobs when the screen accepts its textures, else refused by name in
// frame.result.errors (after trying the larger sizes ProjectedShadowOptions::grow_to_accepted
// asks for). A caster outside the light's beam casts nothing and says nothing.
void cast_caster_shadow(ProjectedFrame &frame, std::size_t light, std::size_t caster);

}  // namespace gs
