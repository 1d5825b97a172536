// `glideshadows demo --window`: the fight in a window (the shim's SDL2 backend) with keys to
// pause and step, orbit and zoom the camera, move the light, switch the technique and the
// shadow size, show the light's view and the shadow texture, and an overlay of frames per
// second and the five step times. The keys are listed by window_key_help().
#pragma once

#include "fight_demo.h"

#include <cstdio>
#include <string>
#include <vector>

namespace gs::demo {

struct WindowSettings {
  DemoSettings demo;             // size, fps (fight seconds per frame when stepping), beam
  std::string technique = "projected";
  TechniqueOptions options;      // the technique's; options.projected.size is the shadow size
  bool start_paused = false;     // start on frame 0, paused
  int max_frames = 0;            // stop after this many frames shown; 0: until Escape or close
};

// One line per key (or key pair) and what it does, for --help and the help overlay.
const std::vector<std::string> &window_key_help();

// Opens the window (GLIDESHIM_BACKEND=sdl unless the environment names another backend) and
// runs until Escape, Q or the window's close button. Every change a key makes is also printed
// to `log` as one line ("paused at 1.25 s", "technique planar", ...). The exit code: 0, or 1
// with a message on stderr when the window cannot be opened or a technique fails.
int play_fight_in_window(const WindowSettings &settings, std::FILE *log);

}  // namespace gs::demo
