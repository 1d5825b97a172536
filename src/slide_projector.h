// Segal et al. 1992's slide projector on the Glide shim: the scene's surfaces lit through
// projected slides, in the paper's passes: depth only; where z equals the stored depth, add each
// projector's slide colour (and the other lights' light); then modulate by the surface colour.
// The slide's (s, t) are the paper's projective coordinates, divided per pixel by the TMU
// (GR_STWHINT_W_DIFF_TMU0). Surfaces behind a projector or facing away get nothing from it.
#pragma once

#include "scene.h"
#include "scene_pass.h"

#include <glide.h>

#include <string>
#include <vector>

namespace gs {

bool is_slide_pattern(const std::string &name);  // checker, rings, grid
// A 64x64 RGB565 slide with a black outer texel, so clamp mode adds nothing outside it.
std::vector<FxU16> slide_texels(const std::string &name);

bool has_slide_projectors(const Scene &scene);
// The scene pass when projectors light the scene (render_scene calls it).
void render_scene_with_projectors(const Scene &scene, const FrameGeometry &frame);

}  // namespace gs
