// The pieces Nguyen 1999's figures share (figures_nguyen.cpp: Figures 1, 4-9, the steps;
// figures_nguyen_planar.cpp: 2, 3; figures_nguyen_texels.cpp: 10-15, the texture's addressing,
// border and filtering; figures_nguyen_formats.cpp: 16, 17, the pixel formats): the
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
// step 2 reads them. `fault` may leave step 5 out (ShadowLeftOut; `frame` then has no job), move the light's matrix
// sideways by 6 texels after step 2 (ShiftedProjection: the texture lands beside the shadow)
// or read `light_words` after step 4 has drawn over them (StaleReadBack).
struct Steps {
  ShadowFrame frame;
  Words light_words;
  bool usable = false;
};
Steps run_steps(const Scene &scene, const ProjectedShadowOptions &options,
                const glm::mat4 &narrowing = glm::mat4(1.0f), FigureFault fault = FigureFault::None);

// Light clip space: the view enlarged 1.3 times and moved sideways by a third of its width,
// so the texture's left border cuts through the fighter from head to foot (Figures 12, 13).
glm::mat4 border_cutting_view();

// The light's view of the fighter as a camera: the same eye, axis, up and field of view as
// step 1, so its 256 x 256 pixels are the shadow texture's texels.
Scene from_the_light(const Scene &scene);

// The shadow texture's alpha nibble as a picture: white 1111b, black 0000b, magenta between.
FigureImage alpha_picture(const Words &words);
Mask alpha_set(const Words &words);  // texels whose alpha nibble is 1111b

// Texels of `mask` (size x size) within `ring` texels of the texture's edge.
long near_border(const Mask &mask, int size, int ring);

// The ray-cast shadow of the mesh step 1 drew (the fighter's simplified shadow mesh, so what
// is measured is the projection, not the simplification) on the floor and the step, and the
// pixels that count: floor and step outside the step's own shadow (the ray caster lets every
// object cast; the figures leave the step's shadow out). False when the scene cannot be cast.
bool true_shadow(Scene scene, Mask &shadow, Mask &receivers);
// The technique's mask against that truth.
MaskErrors against_truth(const Scene &scene, const Words &mask);

}  // namespace gs::figures
