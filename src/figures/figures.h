// The articles' figures, reproduced by our own renderers: Nguyen 1999 (Figures 1-17), Segal
// et al. 1992 (Figures 3, 4) and Everitt et al. 2001 (Figures 2, 4, 5). Each figure is one small
// function in a table; it renders its panels into one image and states, as checks evaluated on
// the rendered pixels, what the article says the figure shows. Adding a figure is adding a
// function (in figures_<source>.cpp, declared in figures_kit.h) and a row of figure_table().
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace gs {

struct FigureImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 8-bit RGB, rows from the top
};

// What the article says the figure shows, and what our pixels measured.
struct FigureCheck {
  std::string claim;
  std::string measured;
  bool passed = false;
};

struct Figure {
  FigureImage image;
  std::string shows;  // what our image shows, panel by panel
  std::vector<FigureCheck> checks;
};

// A deliberate mistake a figure can be rendered with, so that a test can show its checks catch
// it (tests/image/figure_faults_test.cpp). A figure honours the faults that name a step it has
// and renders as usual for the others.
enum class FigureFault {
  None,
  StaleReadBack,       // a panel read back after a later render has overwritten its frame
  WrongBuffer,         // a panel read back from the other buffer (colour for depth, or back)
  InvalidGlideCall,    // a Glide call with an enum Glide 2.x does not define (every figure)
  ShadowLeftOut,       // the shadow texture (or the technique's shadows) left out
  FullStrength,        // the shadow pass at iterated alpha 255 instead of the article's 170
  EyeBesideLight,      // the "from the light" view drawn from a point 0.3 m beside the light
  LightMoved,          // the light drawn 0.3 m beside where the figure says it stands
  FacingInverted,      // Listing 2's facing test inverted
  NoCleanBorder,       // the fitted light view replaced by one whose border cuts the caster
  BorderIgnored,       // the view that should cut the caster replaced by the fitted one
  ShiftedProjection,   // the shadow texture projected through a light matrix moved sideways
  TextureModeSwapped,  // clamp where the figure wraps and wrap where it clamps
  SecondPassLess,      // the second pass at GR_CMP_LESS where the article needs LEQUAL
  PointSampled,        // bilinear (or GL_LINEAR) filtering off where the figure filters
  WrongFormat,         // a texture downloaded as ARGB_1555 instead of its format
};

using FigureMaker = void (*)(Figure &, FigureFault);

struct FigureEntry {
  const char *name;     // "nguyen-7": how --only and the file names call it
  const char *source;   // "Nguyen 1999, Figure 7"
  const char *caption;  // the article's caption, in our words
  FigureMaker make;
};

// Every figure, in the order the index shows them.
const std::vector<FigureEntry> &figure_table();

// `only` is a comma-separated list of names ("nguyen-7", "sgi-3") or bare numbers (Nguyen's
// figure numbers); empty selects every figure. False with `error` naming an unknown entry.
bool select_figures(const std::string &only, std::vector<const FigureEntry *> &selected,
                    std::string &error);

// Each figure renders into a Glide window of this size, opened afresh for it (so no state
// carries over from the figure before: the same figure gives the same bytes alone or in a run).
constexpr int kFigureWindowWidth = 320;
constexpr int kFigureWindowHeight = 256;

// Renders one figure into `figure`, in a new window (after grGlideInit; grGlideShutdown closes
// the last one). False, with `error`, when the window cannot be opened. A Glide error raised
// while it renders becomes a failed check. `fault` renders the figure with that mistake.
bool make_figure(const FigureEntry &entry, Figure &figure, std::string &error,
                 FigureFault fault = FigureFault::None);

bool write_figure_png(const FigureImage &image, const std::string &path, std::string &error);

// DIR/index.html: the figures side by side with the article's caption, what ours shows, and
// each check with its result. `images` are the PNG file names, relative to DIR.
bool write_figure_index(const std::string &path, const std::vector<const FigureEntry *> &entries,
                        const std::vector<Figure> &figures, const std::vector<std::string> &images,
                        std::string &error);

// The `figures` command: renders the selection into `out_dir` (PNG per figure and index.html),
// printing progress and every check to `out`. 0 when every check passed, 1 when one failed or
// something could not be written, 2 for a bad selection.
int run_figures(const std::string &out_dir, const std::string &only, std::FILE *out);

}  // namespace gs
