// The fighting-game demo's driver: the fight (scene/fight_scene.h) rendered frame after frame
// through one shadow technique into a Glide window, each frame written as a PNG, with the
// article's five step times collected for a table. The command-line face is demo_command.cpp.
#pragma once

#include "scene/fight_scene.h"
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
  int frames = 96;
  int width = 640, height = 480;  // screen, pixels
  int fps = 12;                   // frames per second of fight time: 96 frames, one 8 s loop
  int shadow_size = 256;
  ProjectedShadowOptions shadow_options;  // the technique's, for reporting texture sizes
  DemoBeam beam;
  std::string out_dir = "out/demo";
};

// One of a run's warnings (FrameReport::warnings) and how many frames it was among them.
struct WarningCount {
  std::string text;
  int frames = 0;
  bool error = false;  // among FrameReport::errors: a shadow the frame should show is missing
};

struct DemoRun {
  std::vector<std::string> frame_files;  // in order
  std::vector<FrameReport> reports;      // every frame but the first (llvmpipe's compiles)
  std::vector<WarningCount> warnings;    // each once, in the order they first came
  std::vector<int> frames_missing_shadow;  // the frames (from 0) with an error among them
  std::vector<int> texture_sizes;        // per frame, the red and the blue fighter's shadow
                                         // texture sides (what --auto-size chose, or what
                                         // --grow-size drew at), interleaved
};

// The fight at `time` seconds with the chosen beam; frame `index` of a run is at index / fps.
Scene demo_scene_at(FightScene &fight, const DemoSettings &settings, float time);
Scene demo_frame_scene(FightScene &fight, const DemoSettings &settings, int index);

// The side of each fighter's shadow texture under the first light in `scene`, as the projected
// technique fits it (with options.auto_size, from the fighter's size on screen), or the size
// `drawn` (the frame's, FrameReport::shadow_sizes) says it was drawn at (larger where
// options.grow_to_accepted grew it); 0 for a fighter the light cannot give a shadow.
std::vector<int> fighter_texture_sizes(const Scene &scene, const ProjectedShadowOptions &options,
                                       const std::vector<DrawnShadowSize> &drawn = {});

// Counts one frame's warnings into `run` (each once per frame).
void count_warnings(const FrameReport &frame, int index, DemoRun &run);
// The run's warnings as printed lines, each with the frames it was in, errors marked, after a
// line saying how many of `frames` lacked a shadow (and which, the first few).
std::vector<std::string> warning_summary(const DemoRun &run, int frames);

// How much of the frame shows one fighter's shadow on the other: `technique` renders `scene`
// (in the open window, into the back buffer) and its shadow mask is counted on the pixels where
// a fighter is the visible surface. The projected techniques never shadow a caster with its own
// texture, so every such pixel lies in the other fighter's shadow.
struct InterFighterShadow {
  long pixels[2] = {0, 0};  // shadowed pixels on the red and on the blue fighter
  double share = 0.0;       // their sum over the frame's pixels
};
InterFighterShadow measure_inter_fighter_shadow(ShadowTechnique &technique, const Scene &scene);

// "128 in 40 frames, 256 in 56 frames": the texture sides of a run, for the summary.
std::string describe_texture_sizes(const std::vector<int> &sizes);

// Renders the frames through `technique` (the Glide window must be open, width x height) into
// out_dir as frame_NNNN.png after clearing the earlier run's frames there. Progress goes to
// stderr. False with `error` on the first failure.
bool render_fight(const DemoSettings &settings, ShadowTechnique &technique, DemoRun &run,
                  std::string &error);

// The five steps' median times and shares of the frame, as printed lines.
std::vector<std::string> step_table(const std::vector<FrameReport> &reports);

}  // namespace gs::demo
