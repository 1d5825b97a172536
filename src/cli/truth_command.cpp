// `glideshadows truth SCENE.json --mask M.png`: the exact shadow mask by ray casting, and with
// --image the scene lit with exact visibility.
#include "cli/commands.h"
#include "measure/ground_truth.h"
#include "media/media.h"
#include "scene/scene.h"

#include <cstdio>
#include <memory>
#include <string>

namespace gs::cli {
namespace {

struct TruthOptions {
  std::string scene_path, mask, image;
};

int run_truth(const TruthOptions &o) {
  Scene scene;
  std::string error;
  if (!load_scene(o.scene_path, scene, error)) {
    std::fprintf(stderr, "glideshadows truth: %s\n", error.c_str());
    return 1;
  }
  GroundTruth truth;
  if (!compute_ground_truth(scene, truth, error)) {
    std::fprintf(stderr, "glideshadows truth: %s\n", error.c_str());
    return 1;
  }
  if (!media::write_mask_png(o.mask, truth.width, truth.height, truth.shadow, error)) {
    std::fprintf(stderr, "glideshadows truth: cannot write %s: %s\n", o.mask.c_str(), error.c_str());
    return 1;
  }
  std::printf("mask: %s (white: a light blocked by another object)\n", o.mask.c_str());
  if (!o.image.empty()) {
    if (!media::write_rgb_png(o.image, truth.width, truth.height, truth.rgb, error)) {
      std::fprintf(stderr, "glideshadows truth: cannot write %s: %s\n", o.image.c_str(), error.c_str());
      return 1;
    }
    std::printf("image: %s (exact visibility, per-pixel lighting)\n", o.image.c_str());
  }
  return 0;
}

}  // namespace

Command add_truth_command(CLI::App &app) {
  auto o = std::make_shared<TruthOptions>();
  CLI::App *truth = app.add_subcommand("truth", "ray-cast the exact shadow mask (and image) of a scene file");
  truth->add_option("scene", o->scene_path, "scene file")->required();
  truth->add_option("--mask", o->mask, "output: white where another object blocks a light")->required();
  truth->add_option("--image", o->image, "output: the scene lit with exact visibility");
  return {truth, [o] { return run_truth(*o); }};
}

}  // namespace gs::cli
