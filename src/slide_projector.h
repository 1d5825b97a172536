// Segal et al. 1992's projective-texture lights on the Glide shim: slide projectors (3.1) and
// spotlights with beam maps (3.2), in the paper's passes: depth only; where z equals the stored
// depth, add each light's projected texture times its light (and the other lights' light); then
// modulate by the surface colour. The texture's (s, t) are the paper's projective coordinates,
// divided per pixel by the TMU (GR_STWHINT_W_DIFF_TMU0). Surfaces behind a light or facing away
// get nothing from it. A spotlight's attenuation with distance is per vertex, or exact per pixel
// for one spotlight, formed first in the cleared accumulation (see spotlight.h).
#pragma once

#include "scene.h"
#include "scene_pass.h"

#include <glide.h>

#include <string>
#include <vector>

namespace gs {

bool is_slide_pattern(const std::string &name);  // checker, rings, grid
// A projector's RGB565 slide, side x side (64 for the built-in slides, 128 from an image file),
// with a black outer texel, so clamp mode adds nothing outside it.
std::vector<FxU16> slide_texels(const SpotLight &projector, int &side);

// The same slide as colours 0..1 (each 565 field widened by bit replication, as the TMU reads
// it), for renderers that sample it themselves: the ground truth, the plain-GL techniques.
ProjectedImage slide_image(const SpotLight &projector);

// True when a light projects a texture (a slide or a beam map), so the scene needs these passes.
bool needs_projective_passes(const Scene &scene);
// The scene pass when projective lights light the scene (render_scene calls it).
void render_scene_with_projectors(const Scene &scene, const FrameGeometry &frame);

}  // namespace gs
