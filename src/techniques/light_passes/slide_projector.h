// Segal et al. 1992's projective-texture lights on the Glide shim: slide projectors (3.1) and
// spotlights with beam maps (3.2), in the paper's passes: depth only; where z equals the stored
// depth, add each light's projected texture times its light (and the other lights' light); then
// modulate by the surface colour. The texture's (s, t) are the paper's projective coordinates,
// divided per pixel by the TMU (GR_STWHINT_W_DIFF_TMU0). Surfaces behind a light or facing away
// get nothing from it. A spotlight's attenuation with distance is per vertex, or exact per pixel
// for one spotlight, formed first in the cleared accumulation (see spotlight.h).
#pragma once

#include "scene/scene.h"
#include "techniques/light_passes/scene_pass.h"
#include "scene/slides.h"

#include <glide.h>

#include <string>
#include <vector>

namespace gs {

// The TMU0 memory these passes download their textures into, [address, address + bytes): the
// largest is a 128x128 slide in RGB_565. Above the shadow textures' usual range; a shadow
// texture there is loaded again after a scene pass (ShadowTextureMemory::forget).
inline constexpr FxU32 kProjectiveTextureAddress = 0x180000;
inline constexpr FxU32 kProjectiveTextureBytes = 128 * 128 * 2;
// True when a light projects a texture (a slide or a beam map), so the scene needs these passes.
bool needs_projective_passes(const Scene &scene);
// The scene pass when projective lights light the scene (render_scene calls it).
void render_scene_with_projectors(const Scene &scene, const FrameGeometry &frame);

}  // namespace gs
