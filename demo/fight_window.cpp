// The demo's window loop: keys are read with glideShimPollKey between frames, the fight's scene
// is taken from FightScene and then turned by the user's camera and light changes (world space,
// about the vertical axis through the ring's centre), rendered by the chosen technique, and the
// overlays are written through the LFB before the swap. Fight time follows the wall clock
// while playing; paused, '.' and ',' step it by one frame (1 / fps seconds).
#include "fight_window.h"

#include "cli/options.h"
#include "figures/figures_kit.h"
#include "techniques/light_passes/scene_pass.h"
#include "window_overlay.h"

#include <glide_shim.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <thread>

namespace gs::demo {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kShadowSizes[] = {32, 64, 128, 256, 512};
constexpr int kInsetSide = 150;   // screen pixels of each inset picture
constexpr int kInsetMargin = 8;
constexpr int kInsetViewPixels = 160;  // the light's view is rendered this size, then scaled
constexpr unsigned char kWarningColour[3] = {255, 90, 70};  // the missing-shadow panel's text

// What the keys have changed.
struct ViewState {
  float time = 0.0f;           // fight seconds
  bool paused = false;
  float camera_orbit = 0.0f;   // degrees about the vertical axis through the camera's target
  float zoom = 1.0f;           // camera distance factor
  float light_orbit = 0.0f;    // degrees about the vertical axis through the ring's centre
  float light_raise = 0.0f;    // metres added to the light's height
  std::size_t technique = 0;   // index into technique_names()
  int shadow_size = 256;
  bool auto_size = false;
  bool grow_size = false;      // ProjectedShadowOptions::grow_to_accepted
  bool inset = false, overlay = true, help = false;
};

glm::vec3 turned(const glm::vec3 &point, const glm::vec3 &pivot, float degrees) {
  const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0));
  return pivot + glm::vec3(turn * glm::vec4(point - pivot, 0.0f));
}

// The fight's scene at the state's time with the user's camera and light applied.
Scene adjusted_scene(FightScene &fight, const WindowSettings &settings, const ViewState &state) {
  Scene scene = demo_scene_at(fight, settings.demo, state.time);
  Camera &camera = scene.camera;
  camera.position = turned(camera.position, camera.target, state.camera_orbit);
  camera.position = camera.target + (camera.position - camera.target) * state.zoom;
  SpotLight &light = scene.lights.front();
  light.position = turned(light.position, glm::vec3(0.0f), state.light_orbit);
  light.position.y += state.light_raise;
  return scene;
}

std::string upper_name(const std::string &name) {
  std::string text = name;
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

// The light's view (as step 1's camera would see the whole scene) and the red fighter's shadow
// texture as step 2 makes it, both drawn into the back buffer's corner and read back, before
// the frame itself is rendered over them.
struct Insets {
  Picture light_view, texture;
  int texture_size = 0;
};

Insets render_insets(const Scene &scene, const ProjectedShadowOptions &technique_options) {
  Insets insets;
  const SpotLight &light = scene.lights.front();
  const Scene from_light = figures::seen_from(scene, light.position, light.target, light.cone_degrees, kInsetViewPixels);
  render_scene(from_light, project_scene(from_light));
  insets.light_view = read_back_buffer(kInsetViewPixels, kInsetViewPixels);
  ProjectedShadowOptions options = technique_options;
  options.direct_path = false;  // the words are read back from the frame buffer
  LightView view = fit_light_view(scene, FightScene::kFighters[0], 0, options);
  if (!view.usable) return insets;
  if (view.size > 256) {  // a 512 map is four 256 tiles; the inset shows the whole at 256
    options.size = 256;
    options.auto_size = false;
    view = fit_light_view(scene, FightScene::kFighters[0], 0, options);
  }
  render_caster_from_light(scene, FightScene::kFighters[0], view, options, grTexMinAddress(GR_TMU0));
  if (!view.usable) return insets;
  insets.texture = alpha_nibble_picture(read_back_buffer(view.size, view.size));
  insets.texture_size = view.size;
  return insets;
}

std::vector<std::string> overlay_lines(const ViewState &state, const FrameReport &report, double fps,
                                       const std::vector<int> &sizes) {
  // A fighter's texture larger than the size asked for: grown (ProjectedShadowOptions::grow_to_accepted).
  const bool grown = std::any_of(sizes.begin(), sizes.end(), [&](int size) { return size > state.shadow_size; });
  char line[128];
  std::vector<std::string> lines;
  std::snprintf(line, sizeof line, "%.1f FPS  T %.2f S%s", fps, state.time, state.paused ? "  PAUSED" : "");
  lines.emplace_back(line);
  std::snprintf(line, sizeof line, "%s  SHADOW %d%s%s", upper_name(technique_names()[state.technique]).c_str(),
                state.shadow_size, state.auto_size ? " AUTO" : "", state.grow_size ? " GROW" : "");
  lines.emplace_back(line);
  if ((state.auto_size || grown) && sizes.size() == 2) {
    std::snprintf(line, sizeof line, "SIZES: RED %d  BLUE %d", sizes[0], sizes[1]);
    lines.emplace_back(line);
  }
  for (const auto &[name, ms] : report.steps) {
    std::snprintf(line, sizeof line, "%-42s %6.2f MS", upper_name(name).c_str(), ms);
    lines.emplace_back(line);
  }
  std::snprintf(line, sizeof line, "%-42s %6.2f MS", "WHOLE FRAME", report.total_ms);
  lines.emplace_back(line);
  lines.emplace_back("H: KEYS");
  return lines;
}

TechniqueOptions options_for(const WindowSettings &settings, const ViewState &state) {
  TechniqueOptions options = settings.options;
  options.projected.size = state.shadow_size;
  options.projected.auto_size = state.auto_size;
  options.projected.grow_to_accepted = state.grow_size;
  return options;
}

// The frame's errors (shadows it lacks, FrameReport::errors) under a heading, in the overlay's
// font (upper case, no quotes or semicolons) and wrapped to `width` screen pixels at scale 2;
// at most kMissingLines lines, the rest cut short.
std::vector<std::string> missing_shadow_lines(const std::vector<std::string> &errors, int width) {
  constexpr std::size_t kMissingLines = 8;
  std::vector<std::string> lines;
  if (errors.empty()) return lines;
  lines.push_back("SHADOW MISSING IN THIS FRAME:");
  for (const std::string &error : errors) {
    std::string text = upper_name(error);
    text.erase(std::remove(text.begin(), text.end(), '\''), text.end());
    std::replace(text.begin(), text.end(), ';', ',');  // the font has commas, not semicolons
    for (const std::string &line : wrap_for_panel("- " + text, width, 2)) lines.push_back(line);
  }
  if (lines.size() > kMissingLines) lines.resize(kMissingLines), lines.back() += " ...";
  return lines;
}

enum class KeyEffect { View, NewTechnique, Quit };

// What `key` changes in `state`, printed to `log` as one line; whether the technique must be
// made anew or the window closed.
KeyEffect apply_key(int key, ViewState &state, float frame_seconds, std::FILE *log) {
  const std::size_t techniques = technique_names().size();
  KeyEffect effect = KeyEffect::View;
  switch (key) {
    case ' ':
      state.paused = !state.paused;
      std::fprintf(log, "glideshadows demo: %s at %.3f s\n", state.paused ? "paused" : "playing", state.time);
      break;
    case '.': case ',':
      state.paused = true;
      state.time = std::max(0.0f, state.time + (key == '.' ? frame_seconds : -frame_seconds));
      std::fprintf(log, "glideshadows demo: paused at %.3f s\n", state.time);
      break;
    case GLIDESHIM_KEY_LEFT: case GLIDESHIM_KEY_RIGHT:
      state.camera_orbit += key == GLIDESHIM_KEY_LEFT ? -10.0f : 10.0f;
      std::fprintf(log, "glideshadows demo: camera orbit %.0f degrees\n", state.camera_orbit);
      break;
    case GLIDESHIM_KEY_UP: case GLIDESHIM_KEY_DOWN:
      state.zoom = std::clamp(state.zoom * (key == GLIDESHIM_KEY_UP ? 0.9f : 1.0f / 0.9f), 0.4f, 2.5f);
      std::fprintf(log, "glideshadows demo: camera zoom %.2f\n", state.zoom);
      break;
    case 'a': case 'd':
      state.light_orbit += key == 'a' ? -10.0f : 10.0f;
      std::fprintf(log, "glideshadows demo: light orbit %.0f degrees\n", state.light_orbit);
      break;
    case 'w': case 's':
      state.light_raise = std::clamp(state.light_raise + (key == 'w' ? 0.2f : -0.2f), -1.6f, 4.0f);
      std::fprintf(log, "glideshadows demo: light raised %.1f m\n", state.light_raise);
      break;
    case 't': case 'T':
      state.technique = (state.technique + (key == 't' ? 1 : techniques - 1)) % techniques;
      effect = KeyEffect::NewTechnique;
      break;
    case '+': case '=': case '-': {
      const int *size = std::find(std::begin(kShadowSizes), std::end(kShadowSizes), state.shadow_size);
      if (key == '-' && size != std::begin(kShadowSizes)) --size;
      if (key != '-' && size + 1 != std::end(kShadowSizes)) ++size;
      state.shadow_size = size == std::end(kShadowSizes) ? 256 : *size;
      effect = KeyEffect::NewTechnique;
      break;
    }
    case 'u':
      state.auto_size = !state.auto_size;
      effect = KeyEffect::NewTechnique;
      break;
    case 'g':
      state.grow_size = !state.grow_size;
      effect = KeyEffect::NewTechnique;
      break;
    case 'v':
      state.inset = !state.inset;
      std::fprintf(log, "glideshadows demo: inset %s\n", state.inset ? "on" : "off");
      break;
    case 'o':
      state.overlay = !state.overlay;
      std::fprintf(log, "glideshadows demo: overlay %s\n", state.overlay ? "on" : "off");
      break;
    case 'h': case GLIDESHIM_KEY_F1:
      state.help = !state.help;
      std::fprintf(log, "glideshadows demo: help %s\n", state.help ? "on" : "off");
      break;
    case 'r':
      state.camera_orbit = state.light_orbit = state.light_raise = 0.0f;
      state.zoom = 1.0f;
      std::fprintf(log, "glideshadows demo: camera and light reset\n");
      break;
    case GLIDESHIM_KEY_ESCAPE: case 'q': return KeyEffect::Quit;
    default: break;
  }
  return effect;
}

}  // namespace

const std::vector<std::string> &window_key_help() {
  static const std::vector<std::string> help = {
      "SPACE        pause / play",
      ". ,          step one frame forward / back (pauses)",
      "LEFT RIGHT   orbit the camera",
      "UP DOWN      zoom in / out",
      "A D          move the light round the ring",
      "W S          raise / lower the light",
      "T SHIFT+T    next / previous technique",
      "+ -          larger / smaller shadow texture",
      "U            shadow size follows the fighters on screen (auto)",
      "G            a shadow too coarse is drawn larger, not left out (grow)",
      "V            inset: the view from the light and the shadow texture",
      "O            overlay: frames per second and step times",
      "R            reset camera and light",
      "H F1         this help",
      "ESC Q        quit"};
  return help;
}

int play_fight_in_window(const WindowSettings &settings, std::FILE *log) {
  setenv("GLIDESHIM_BACKEND", "sdl", 0);  // a backend the user named is kept
  const int width = settings.demo.width, height = settings.demo.height;
  if (!cli::open_window(width, height)) return 1;
  ViewState state;
  state.paused = settings.start_paused;
  state.shadow_size = settings.options.projected.size;
  state.auto_size = settings.options.projected.auto_size;
  state.grow_size = settings.options.projected.grow_to_accepted;
  const std::vector<std::string> &names = technique_names();
  const auto named = std::find(names.begin(), names.end(), settings.technique);
  state.technique = named == names.end() ? 0 : static_cast<std::size_t>(named - names.begin());
  std::string error;
  std::unique_ptr<ShadowTechnique> technique = make_technique(names[state.technique], options_for(settings, state), error);
  FightScene fight(width, height, state.shadow_size);
  std::fprintf(log, "glideshadows demo: window %dx%d (backend %s), technique %s; H for the keys\n", width, height,
               glideShimBackendName(), names[state.technique].c_str());
  std::fflush(log);
  const float frame_seconds = 1.0f / static_cast<float>(settings.demo.fps);
  bool dirty = true, quit = false;
  int shown = 0;
  double fps = 0.0;
  Clock::time_point last = Clock::now();
  while (!quit && technique) {
    bool remake = false;
    for (int key = glideShimPollKey(); key != GLIDESHIM_KEY_NONE; key = glideShimPollKey()) {
      dirty = true;
      const KeyEffect effect = apply_key(key, state, frame_seconds, log);
      quit = quit || effect == KeyEffect::Quit;
      remake = remake || effect == KeyEffect::NewTechnique;
    }
    if (remake) {
      technique = make_technique(names[state.technique], options_for(settings, state), error);
      std::fprintf(log, "glideshadows demo: technique %s, shadow texture %d%s%s\n", names[state.technique].c_str(),
                   state.shadow_size, state.auto_size ? " (auto)" : "", state.grow_size ? " (grow)" : "");
      if (!technique) break;
    }
    std::fflush(log);
    if (quit || glideShimWindowClosed()) break;
    const Clock::time_point now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - last).count();
    if (!state.paused) {
      state.time += static_cast<float>(std::min(elapsed, 0.25));
      dirty = true;
    }
    last = now;
    if (!dirty) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      continue;
    }
    const Scene scene = adjusted_scene(fight, settings, state);
    const TechniqueOptions options = options_for(settings, state);
    const Insets insets = state.inset ? render_insets(scene, options.projected) : Insets{};
    const FrameReport report = technique->render(scene, true);
    if (state.inset) {
      draw_picture(insets.light_view, width - kInsetSide - kInsetMargin - 2, kInsetMargin, kInsetSide);
      draw_picture(insets.texture, width - kInsetSide - kInsetMargin - 2, 2 * kInsetMargin + kInsetSide + 2, kInsetSide);
    }
    if (!state.paused && elapsed > 0.0) fps = fps == 0.0 ? 1.0 / elapsed : 0.9 * fps + 0.1 / elapsed;
    if (state.overlay) {
      const std::vector<int> sizes = fighter_texture_sizes(scene, options.projected, report.shadow_sizes);
      draw_text_panel(overlay_lines(state, report, fps, sizes), kInsetMargin, kInsetMargin, 2, width, height);
    }
    // A shadow the frame should show and does not, said on screen whether the overlay is on or
    // not: the frame is wrong.
    const std::vector<std::string> missing = missing_shadow_lines(report.errors, width - 2 * kInsetMargin);
    if (!missing.empty()) {
      const int panel_top = height - kInsetMargin - text_panel_height(static_cast<int>(missing.size()), 2);
      draw_text_panel(missing, kInsetMargin, panel_top, 2, width, height, kWarningColour);
    }
    if (state.help) draw_text_panel(window_key_help(), width / 8, height / 4, 2, width, height);
    grBufferSwap(1);
    dirty = false;
    if (state.paused) {  // a line per frame shown while paused: what scripts and tests wait for
      std::fprintf(log, "glideshadows demo: showing %.3f s\n", state.time);
      std::fflush(log);
    }
    if (settings.max_frames > 0 && ++shown >= settings.max_frames) break;
  }
  if (!technique) std::fprintf(stderr, "glideshadows demo: %s\n", error.c_str());
  std::fprintf(log, "glideshadows demo: window closed\n");
  std::fflush(log);
  grGlideShutdown();
  return technique ? 0 : 1;
}

}  // namespace gs::demo
