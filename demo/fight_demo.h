// The fighting-game demo's driver: the fight (scene/fight_scene.h) rendered frame after frame
// through one shadow technique into a Glide window, each frame written as a PNG, with the
// article's five step times collected for a table. The command-line face is demo_command.cpp.
#pragma once

#include "techniques/technique.h"

#include <string>
#include <vector>

namespace gs::demo {

// The demo's spotlight as a projective-texture light (Segal et al. 3.2).
struct DemoBeam {
  std::string beam;                  // empty: the plain cone; else a built-in beam pattern
  std::string attenuation = "none";  // none, vertex, exact
};

struct DemoSettings {
  int frames = 48;
  int width = 640, height = 480;  // screen, pixels
  int fps = 30;                   // frames per second of fight time
  int shadow_size = 256;
  DemoBeam beam;
  std::string out_dir = "out/demo";
};

struct DemoRun {
  std::vector<std::string> frame_files;  // in order
  std::vector<FrameReport> reports;      // every frame but the first (llvmpipe's compiles)
  std::vector<std::string> warnings;     // each once
};

// Renders the frames through `technique` (the Glide window must be open, width x height) into
// out_dir as frame_NNNN.png after clearing the earlier run's frames there. Progress goes to
// stderr. False with `error` on the first failure.
bool render_fight(const DemoSettings &settings, ShadowTechnique &technique, DemoRun &run,
                  std::string &error);

// The five steps' median times and shares of the frame, as printed lines.
std::vector<std::string> step_table(const std::vector<FrameReport> &reports);

}  // namespace gs::demo
