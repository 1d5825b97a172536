// The Voodoo's 16-bit depth codes and how the shim stands for them in a 24-bit GL buffer:
// Z-buffer depth is ooz/65535 (larger ooz is nearer); W-buffer depth is 1/w itself, which is
// affine in screen space as the hardware iterates it, with every ordering compare turned around.
#pragma once

#include <glide.h>

#include "context.h"

namespace glide_shim {

// GL window depth [0,1] for a vertex under the current depth mode and bias.
float vertex_depth(const DepthState &depth, float ooz, float oow);
// The GL depth that a 16-bit depth code (as given to grBufferClear) stands for.
double gl_depth_from_code(FxU16 code, bool w_buffer);
// The hardware's 16-bit code for a GL depth, as an aux-buffer LFB read returns it.
FxU16 code_from_gl_depth(float depth, bool w_buffer);
// W-buffer code of 1/w: 4096 steps per octave of w, 0 for 1/w >= 1 (as MAME and 86Box implement it).
FxU16 w_code(double oow);
double oow_from_w_code(FxU16 code);

bool is_w_buffer(GrDepthBufferMode_t mode);
bool is_z_buffer(GrDepthBufferMode_t mode);
// The COMPARE_TO_BIAS modes: the depth test compares grDepthBiasLevel, not the pixel's depth,
// with the stored depth, and the pixel's depth carries no bias.
bool compares_to_bias(GrDepthBufferMode_t mode);

// For the COMPARE_TO_BIAS modes: the stored GL depths whose 16-bit code passes
// `bias_level (as unsigned 16 bits) OP code`, as closed intervals [low, high] of GL window depth
// on the 24-bit buffer's levels. Returns how many (0 for NEVER or an empty set, 2 for NOTEQUAL
// on both sides of the equal codes, else 1).
struct DepthInterval {
  double low, high;
};
int bias_compare_intervals(const DepthState &depth, DepthInterval intervals[2]);

}  // namespace glide_shim
