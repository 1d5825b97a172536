// The caster's textures against the screen (screen_check.h). Spaces: Glide screen pixels for the
// footprints, estimates and budgets; each texture's light view only to find the receiver
// triangles' centres lost to the snap.
#include "techniques/projected/screen_check.h"

#include "techniques/projected/receiver_cells.h"
#include "techniques/texel_error/texel_footprint.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace gs {

ScreenCheck check_against_screen(ProjectedFrame &frame, std::size_t light, std::size_t caster,
                                 int size) {
  const Scene &scene = frame.scene;
  std::vector<FootprintSample> samples;
  for (const ShadowJob &job : frame.caster_jobs) {
    samples.insert(samples.end(), job.receivers.footprints.begin(), job.receivers.footprints.end());
  }
  const FootprintSample coarsest = shadow_footprint(
      std::move(samples),
      kFootprintIgnoredScreenShare * static_cast<float>(scene.width * scene.height));
  frame.result.texel_footprint_px =
      std::max(frame.result.texel_footprint_px, coarsest.pixels_per_texel);
  // The error along the shadow's edges, over all its textures (shadow_edge_error.h).
  EdgeErrorEstimate edge_error;
  std::size_t edge_error_receiver = 0;
  float edge_error_receiver_pixels = -1.0f;
  for (const ShadowJob &job : frame.caster_jobs) {
    edge_error.add(job.receivers.edge_error);
    if (job.receivers.edge_error_receiver_pixels > edge_error_receiver_pixels) {
      edge_error_receiver = job.receivers.edge_error_receiver;
      edge_error_receiver_pixels = job.receivers.edge_error_receiver_pixels;
    }
  }
  // Pixel centres thin receiver triangles lose to the snap, each perhaps wrong (receiver_cells.h).
  int lost = 0;
  for (const ShadowJob &job : frame.caster_jobs) {
    lost += centres_lost_to_snap(job.view, job.receivers.triangles, frame.options.projective,
                                 scene.width, scene.height);
  }
  // The frame's budget is shared: casters take it in the scene's order, and one that would
  // overdraw it is refused.
  EdgeErrorEstimate within_budget = edge_error;
  for (float &pixels : within_budget.pixels) pixels += frame.edge_error_taken;
  const bool too_coarse = coarsest.pixels_per_texel > frame.largest_footprint;
  // The budget (edge_error_budget, exact) is counted only where a decision needs it: a frame
  // whose error fits under a lower bound of it (the receivers' large triangles wholly on the
  // screen, counted until there are pixels enough) is accepted as the exact budget would accept
  // it, as the bound is never above the budget. Most shadowed demo frames settle so (-5.3 M
  // instructions of 171.6 M, the same bytes and decisions).
  frame.edge_error_asked = frame.edge_error_asked || edge_error.pixels[0] > 0.0f || lost > 0;
  if (!frame.largest_edge_error && frame.edge_error_asked) {
    const float needed = within_budget.pixels[0] + static_cast<float>(lost);  // screen pixels
    if (!frame.edge_error_at_least || needed > *frame.edge_error_at_least) {
      constexpr float kLeastTriangleArea = 64.0f;  // screen pixels
      const float enough = (4.0f * needed + 16.0f) / kEdgeErrorReceiverShare;
      frame.edge_error_at_least = std::floor(
          kEdgeErrorReceiverShare *
          receiver_screen_pixels_at_least(scene, frame.geometry, kLeastTriangleArea, enough));
    }
    if (too_coarse || needed > *frame.edge_error_at_least) {
      frame.largest_edge_error = edge_error_budget(scene, frame.geometry);
    }
  }
  EdgeErrorEstimate with_lost = edge_error;  // the lost centres count at every size
  for (float &pixels : with_lost.pixels) pixels += static_cast<float>(lost);
  EdgeErrorEstimate at_larger_sizes = with_lost;
  at_larger_sizes.add(frame.edge_error_of_all);
  frame.edge_error_of_all.add(with_lost);
  ScreenCheck check;
  check.edge_error_pixels = edge_error.pixels[0] + static_cast<float>(lost);
  if (!too_coarse && lost > 0 && frame.largest_edge_error &&
      within_budget.pixels[0] + static_cast<float>(lost) > *frame.largest_edge_error) {
    check.reason = snapped_receivers_reason(scene, light, caster, lost, frame.edge_error_taken,
                                            *frame.largest_edge_error);
    return check;  // no size draws those centres
  }
  if (too_coarse ||
      (frame.largest_edge_error && within_budget.pixels[0] > *frame.largest_edge_error)) {
    constexpr int kLargestSize = 512;  // four 256x256 textures
    check.accepted =
        smallest_accepted_size(size, kLargestSize, coarsest.pixels_per_texel,
                               frame.largest_footprint, at_larger_sizes, frame.largest_edge_error);
    check.reason =
        too_coarse ? texel_footprint_reason(scene, light, caster, coarsest.receiver,
                                            coarsest.pixels_per_texel, frame.largest_footprint,
                                            size, accepted_size_words(check.accepted))
                   : shadow_edge_error_reason(scene, light, caster, edge_error_receiver,
                                              frame.edge_error_taken, within_budget,
                                              *frame.largest_edge_error, size, check.accepted);
  }
  return check;
}

}  // namespace gs
