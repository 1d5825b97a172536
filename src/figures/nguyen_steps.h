// The pieces Nguyen 1999's figures share (figures_nguyen.cpp: Figures 1, 4-9, the steps;
// figures_nguyen_texels.cpp: Figures 10-17, the texture's addressing, border and format): the
// article's scene objects, its five steps run one by one with step 1's words kept, the light's
// view as a camera, and the shadow texture's alpha as a picture and a mask.
#pragma once

#include "figures/figures_kit.h"
#include "measure/metrics.h"

#include <glm/glm.hpp>

namespace gs::figures {

constexpr std::size_t kFloor = 0, kStep = 1, kFighter = 2;  // article_scene()'s objects

// The article's five steps for the fighter under the scene's light, one texture, with the
// light's view optionally changed by `narrowing`, a light clip space transform (identity: the
// fitted view with its clean border; Figures 12 and 13 narrow it until the caster crosses the
// texture's border). Leaves the frame in the back buffer; `light_words` are step 1's words, as
// step 2 reads them.
struct Steps {
  ShadowFrame frame;
  Words light_words;
  bool usable = false;
};
Steps run_steps(const Scene &scene, const ProjectedShadowOptions &options,
                const glm::mat4 &narrowing = glm::mat4(1.0f));

// The light's view of the fighter as a camera: the same eye, axis, up and field of view as
// step 1, so its 256 x 256 pixels are the shadow texture's texels.
Scene from_the_light(const Scene &scene);

// The shadow texture's alpha nibble as a picture: white 1111b, black 0000b, magenta between.
FigureImage alpha_picture(const Words &words);
Mask alpha_set(const Words &words);  // texels whose alpha nibble is 1111b

// Texels of `mask` (size x size) within `ring` texels of the texture's edge.
long near_border(const Mask &mask, int size, int ring);

// The technique's mask against the ray-cast truth on the pixels of the floor and the step,
// the truth cast by the mesh step 1 drew (the fighter's simplified shadow mesh), so what is
// measured is the projection, not the simplification. The ray caster lets every object cast,
// so the step's own shadow (which the figures leave out) is taken out of the comparison.
MaskErrors against_truth(Scene scene, const Words &mask);

}  // namespace gs::figures
