// What the figure functions share: reading the frame buffer back, turning 565 words into the
// picture a monitor shows, laying panels out with burned-in labels, pixel sets and the checks
// made from them, and the scenes the figures are drawn from. Also the figure functions
// themselves, one per figure, which figure_table() lists.
#pragma once

#include "figures/figures.h"
#include "techniques/projected/projected_shadow.h"
#include "scene/scene.h"
#include "techniques/technique.h"

#include <glide.h>

#include <cstdint>
#include <string>
#include <vector>

namespace gs::figures {

constexpr float kListing4Gamma = 0.8f;  // grGammaCorrectionValue in the article's Listing 4

// A region of 16-bit words read back through the LFB, rows from the top.
struct Words {
  int width = 0, height = 0;
  std::vector<FxU16> data;
  FxU16 at(int x, int y) const { return data[static_cast<std::size_t>(y * width + x)]; }
};
// The top-left width x height of a buffer (colour: 565 words; aux: depth codes).
Words read_back(int width, int height, GrBuffer_t buffer = GR_BUFFER_BACKBUFFER);

// One flag per pixel, rows from the top.
using Mask = std::vector<std::uint8_t>;
long count(const Mask &mask);
long count_both(const Mask &a, const Mask &b);
Mask non_zero(const Words &words);

// 565 words as the monitor shows them: widened by bit replication, then through the gamma
// table Glide's scan-out applies (the shim's CLUT: 32 entries, interpolated in eighths).
FigureImage to_image(const Words &words, float gamma);
FigureImage magnified(const FigureImage &image, int factor);  // nearest neighbour
FigureImage filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b);

struct Panel {
  FigureImage image;
  std::string label;  // burned under the panel in the plot's bitmap font (upper case)
};
// Panels side by side on a dark background, each with its label underneath.
FigureImage compose(const std::vector<Panel> &panels);

FigureCheck check(const std::string &claim, bool passed, const std::string &measured);
std::string format(const char *pattern, ...) __attribute__((format(printf, 1, 2)));

// The frame and the shadow mask (white where the technique darkened a pixel) of `scene`, in
// the figures' window; `technique` is a technique_names() entry.
Words render_frame(const std::string &technique, const TechniqueOptions &options,
                   const Scene &scene, Words *mask = nullptr);
// The technique a figure draws its shadows with: `technique`, or "none" under
// FigureFault::ShadowLeftOut.
std::string shadowed_by(const std::string &technique, FigureFault fault);
// Pixels where object `index` is the visible surface (drawn flat white, everything else black).
Mask coverage(Scene scene, std::size_t index);
// The same scene seen from `eye` towards `target` through a square size x size view.
Scene seen_from(Scene scene, const glm::vec3 &eye, const glm::vec3 &target, float fov_degrees,
                int size);
// The figures' version of Nguyen's scene: a fighter (the caster) in guard on a floor, a step
// behind him the shadow climbs, and the spotlight in front, above and to his right.
Scene article_scene();
// How much of an unshadowed pixel's green a shadowed one lost (0: none, 1: all; the 6-bit
// green field is the finest of 565), 0 for a black unshadowed pixel.
double darkening(FxU16 unshadowed, FxU16 shadowed);

}  // namespace gs::figures

namespace gs {

// Nguyen 1999 (figures_nguyen.cpp).
void figure_nguyen_1(Figure &figure, FigureFault fault);
void figure_nguyen_2(Figure &figure, FigureFault fault);  // figures_nguyen_planar.cpp
void figure_nguyen_3(Figure &figure, FigureFault fault);
void figure_nguyen_4(Figure &figure, FigureFault fault);
void figure_nguyen_5(Figure &figure, FigureFault fault);
void figure_nguyen_6(Figure &figure, FigureFault fault);
void figure_nguyen_7(Figure &figure, FigureFault fault);
void figure_nguyen_8(Figure &figure, FigureFault fault);
void figure_nguyen_9(Figure &figure, FigureFault fault);
void figure_nguyen_10(Figure &figure, FigureFault fault);
void figure_nguyen_11(Figure &figure, FigureFault fault);
void figure_nguyen_12(Figure &figure, FigureFault fault);
void figure_nguyen_13(Figure &figure, FigureFault fault);
void figure_nguyen_14(Figure &figure, FigureFault fault);
void figure_nguyen_15(Figure &figure, FigureFault fault);
void figure_nguyen_16(Figure &figure, FigureFault fault);
void figure_nguyen_17(Figure &figure, FigureFault fault);
// Segal et al. 1992 (figures_sgi.cpp).
void figure_sgi_3(Figure &figure, FigureFault fault);
void figure_sgi_4(Figure &figure, FigureFault fault);
// Everitt et al. 2001 (figures_everitt.cpp).
void figure_everitt_2(Figure &figure, FigureFault fault);
void figure_everitt_4(Figure &figure, FigureFault fault);
void figure_everitt_5(Figure &figure, FigureFault fault);

}  // namespace gs
