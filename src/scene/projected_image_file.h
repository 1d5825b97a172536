// Slides and beam maps read from image files (PNG, JPEG, ... through OpenImageIO), for scene
// files. The decoding lives in the image files module (media/image_files.h), loaded the first
// time an image is read, so that programs that read no image (the fight, the benchmarks) do not
// load OpenImageIO and its ~260 libraries.
#pragma once

#include "scene/scene.h"

#include <string>

namespace gs {

// The image at `path` resampled to side x side (RGB clamped to 0..1, row 0 at the top). False
// with `error` naming the file (or the module, when it cannot be loaded) on any problem.
bool load_projected_image(const std::string &path, int side, ProjectedImage &image,
                          std::string &error);

}  // namespace gs
