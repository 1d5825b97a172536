// A slide projector's slide as data (Segal et al. 1992, 3.1): the built-in patterns and slides
// read from image files, as 565 texels and as colours. The passes that project them are in
// techniques/light_passes/slide_projector.h.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gs {

bool is_slide_pattern(const std::string &name);  // checker, rings, grid
// A projector's RGB565 slide, side x side (64 for the built-in slides, 128 from an image file),
// with a black outer texel, so clamp mode adds nothing outside it.
std::vector<std::uint16_t> slide_texels(const SpotLight &projector, int &side);

// The same slide as colours 0..1 (each 565 field widened by bit replication, as the TMU reads
// it), for renderers that sample it themselves: the ground truth, the plain-GL techniques.
ProjectedImage slide_image(const SpotLight &projector);

}  // namespace gs
