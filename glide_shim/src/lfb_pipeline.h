// Linear-frame-buffer writes through the pixel pipeline (grLfbLock with pixelPipeline FXTRUE).
#pragma once

#include "context.h"

#include <vector>

namespace glide_shim {

// One written pixel as the hardware expands the LFB data (MAME's expand_lfb_data): 8-bit colour
// with 5- and 6-bit fields widened by bit replication, the alpha of the data or zaColor's, and
// the depth code of the data or zaColor's.
struct LfbPixel {
  int x, row;  // frame-buffer pixel; row counted from the top whatever the lock's origin
  Rgba8 color;
  FxU16 depth;
};

// Runs `pixels` through the pixel pipeline into `buffer` (FRONT or BACK) with the context's
// current state, as the Voodoo 1 runs a pipelined LFB write (MAME voodoo_renderer::pixel_pipeline):
// clip window, depth test against the written depth code (no bias), chroma key on the written
// colour, alpha test on its alpha, fog from the depth code, alpha blending, dither, then the
// colour and depth writes per their masks. No colour combine or texturing. `write_color` false
// (a ZA16 lock) writes depth only.
void write_through_pipeline(GlideContext &context, GrBuffer_t buffer, bool write_color,
                            const std::vector<LfbPixel> &pixels);

}  // namespace glide_shim
