// The check that ends steps 1 to 3 of a caster's shadow (caster_shadow.cpp): its textures'
// texels against the screen where the shadow falls, and the error along its edges against the
// frame's budget. Spaces: Glide screen pixels for every count and budget here.
#pragma once

#include "techniques/projected/projected_frame.h"
#include "techniques/texel_error/shadow_edge_error.h"

#include <cstddef>
#include <optional>
#include <string>

namespace gs {

// The caster's textures (frame.caster_jobs) against the screen: how many pixels their texels
// span where its shadow's edge can fall (texel_footprint.h) and the error along its edges
// (shadow_edge_error.h), within the frame's budget shared by the casters in the scene's order.
// A `reason` to refuse the shadow when they are too coarse, with the size that would be accepted.
struct ScreenCheck {
  std::optional<std::string> reason;
  AcceptedSize accepted;
  float edge_error_pixels = 0.0f;  // the shadow's estimate, which it takes from the budget
};


// Checks frame.caster_jobs, the textures of `caster`'s shadow from `light` made at `size`, and
// updates the frame's footprint, budget bound and every shadow's estimate at larger sizes.
ScreenCheck check_against_screen(ProjectedFrame &frame, std::size_t light, std::size_t caster,
                                 int size);

}  // namespace gs
