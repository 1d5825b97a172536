// `glideshadows render SCENE.json`: a scene file through one technique to a PNG, and with --mask
// the technique's shadow mask.
#include "cli/commands.h"
#include "cli/options.h"
#include "scene/scene.h"

#include <glide.h>
#include <glide_shim.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

namespace gs::cli {
namespace {

struct RenderOptions {
  std::string scene_path, out = "render.png", mask;
  int shadow_size = 0;  // 0: each light's own shadow_size
  bool allow_missing_shadows = false;
  TechniqueChoice choice;
};

int run_render(const RenderOptions &o) {
  Scene scene;
  std::string error;
  if (!load_scene(o.scene_path, scene, error)) {
    std::fprintf(stderr, "glideshadows render: %s\n", error.c_str());
    return 1;
  }
  std::unique_ptr<ShadowTechnique> technique =
      make_technique(o.choice.name, technique_options(o.choice, o.shadow_size), error);
  if (!technique) {
    std::fprintf(stderr, "glideshadows render: %s\n", error.c_str());
    return 2;
  }
  if (!open_window(scene.width, scene.height)) return 1;
  const FrameReport frame = technique->render(scene, false);
  // A shadow the frame should show and does not is an error (exit 1) unless the user allowed it.
  const char *missing = o.allow_missing_shadows ? "warning" : "error";
  for (const std::string &w : frame.warnings) {
    const bool is_error =
        std::find(frame.errors.begin(), frame.errors.end(), w) != frame.errors.end();
    std::fprintf(stderr, "glideshadows render: %s: %s\n", is_error ? missing : "warning", w.c_str());
  }
  for (const std::string &e : frame.errors) {
    if (std::find(frame.warnings.begin(), frame.warnings.end(), e) == frame.warnings.end())
      std::fprintf(stderr, "glideshadows render: %s: %s\n", missing, e.c_str());
  }
  bool ok = glideShimWritePng(GR_BUFFER_BACKBUFFER, o.out.c_str());
  if (ok) std::printf("image: %s\n", o.out.c_str());
  if (ok && !o.mask.empty()) {
    const float gamma = 1.0f;  // the mask is data, not a picture: no gamma
    grGammaCorrectionValue(gamma);
    technique->render_mask(scene);
    ok = glideShimWritePng(GR_BUFFER_BACKBUFFER, o.mask.c_str());
    if (ok) std::printf("mask: %s (white: pixels the technique darkened)\n", o.mask.c_str());
  }
  if (!ok) std::fprintf(stderr, "glideshadows render: %s\n", glideShimGetLastErrorMessage());
  grGlideShutdown();
  if (ok && !frame.errors.empty() && !o.allow_missing_shadows) {
    std::fprintf(stderr,
                 "glideshadows render: the frame misses shadows (above); --allow-missing-shadows "
                 "accepts it\n");
    return 1;
  }
  return ok ? 0 : 1;
}

}  // namespace

Command add_render_command(CLI::App &app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App *render = app.add_subcommand("render", "render a scene file (JSON, docs/scene_format.md)");
  render->add_option("scene", o->scene_path, "scene file")->required();
  render->add_option("--out", o->out, "output PNG (PNG whatever the name: /dev/null discards it)")->capture_default_str();
  render->add_option("--mask", o->mask, "also write the shadow mask PNG (white: darkened by the technique)");
  render->add_flag("--allow-missing-shadows", o->allow_missing_shadows,
                   "exit 0 even when the technique cannot cast a shadow the scene has (it says which)");
  add_technique_options(*render, o->choice, o->shadow_size);
  render->get_option("--shadow-size")
      ->description("shadow map side, 32..4096 (default: each light's shadow_size); the projected "
                    "techniques draw at most 512, as four 256x256 textures");

  return {render, [o] { return run_render(*o); }};
}

}  // namespace gs::cli
