// Nguyen 1999's figures 10-15: the shadow texture's addressing (clamp and wrap), its border,
// the receivers drawn twice, and its filtering, drawn by the technique's own steps.
// Spaces: world; the light's 256 x 256 view (pixels = texels, y down); the camera's screen
// (pixels, y down); Glide texture units (0..256).
#include "figures/figures_kit.h"
#include "figures/nguyen_steps.h"

#include "measure/metrics.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide_shim.h>
#include <glideutl.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace gs {
namespace {

using figures::alpha_picture;
using figures::alpha_set;
using figures::against_truth;
using figures::check;
using figures::format;
using figures::kFloor;
using figures::kListing4Gamma;
using figures::near_border;
using figures::run_steps;
using figures::Steps;
using figures::Words;

}  // namespace

namespace {

// Figures 10 and 11: a 16 x 16 RGB 565 texture on a 192 x 192 square whose (s, t) run from -1
// to 2 (Glide units -256..512), point sampled: 64 pixels per period, 4 per texel.
constexpr int kSquareLeft = 32, kSquareSide = 192, kPeriod = 64, kTexels = 16;

std::vector<FxU16> square_texture() {
  std::vector<FxU16> texels(kTexels * kTexels);
  for (int y = 0; y < kTexels; ++y) {
    for (int x = 0; x < kTexels; ++x) {
      FxU16 texel = ((x / 4 + y / 4) % 2 == 0) ? 0xC618 : 0x4208;  // light and dark grey
      if (x == y || x + y == kTexels - 1) texel = 0xFFE0;        // yellow diagonals
      if (y == 0) texel = 0xF800;                                // red top row
      if (y == kTexels - 1) texel = 0x001F;                      // blue bottom row
      if (x == 0) texel = 0x07E0;                                // green left column
      if (x == kTexels - 1) texel = 0xF81F;                      // magenta right column
      texels[static_cast<std::size_t>(y * kTexels + x)] = texel;
    }
  }
  return texels;
}

Words draw_square(GrTextureClampMode_t mode) {
  std::vector<FxU16> texels = square_texture();
  GrTexInfo info{GR_LOD_16, GR_LOD_16, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  const FxU32 address = grTexMinAddress(GR_TMU0);
  grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexClampMode(GR_TMU0, mode, mode);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_POINT_SAMPLED);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                 GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grCullMode(GR_CULL_DISABLE);
  grDitherMode(GR_DITHER_DISABLE);  // exact texel colours and background
  grBufferClear(0x202020, 0, 0);
  GrVertex v[4] = {};
  const float low = kSquareLeft, high = kSquareLeft + kSquareSide;
  const float corners[4][2] = {{low, low}, {high, low}, {high, high}, {low, high}};
  for (int i = 0; i < 4; ++i) {
    v[i].x = corners[i][0], v[i].y = corners[i][1], v[i].oow = 1.0f;
    v[i].tmuvtx[0].sow = corners[i][0] == low ? -256.0f : 512.0f;
    v[i].tmuvtx[0].tow = corners[i][1] == low ? -256.0f : 512.0f;
  }
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
  const Words words = figures::read_back(kSquareLeft * 2 + kSquareSide, kSquareLeft * 2 + kSquareSide);
  set_scene_state();
  return words;
}

FigureImage texture_picture() {
  Words words;
  words.width = words.height = kTexels;
  words.data = square_texture();
  return figures::magnified(figures::to_image(words, 1.0f), 8);
}

// Pixels of the square whose colour differs from the pixel `source` maps them to.
template <typename Map>
long mismatches(const Words &square, Map source) {
  long n = 0;
  for (int y = kSquareLeft; y < kSquareLeft + kSquareSide; ++y) {
    for (int x = kSquareLeft; x < kSquareLeft + kSquareSide; ++x) {
      const glm::ivec2 from = source(x, y);
      n += square.at(x, y) != square.at(from.x, from.y);
    }
  }
  return n;
}

}  // namespace

void figure_nguyen_10(Figure &figure, FigureFault fault) {
  const Words square = draw_square(fault == FigureFault::TextureModeSwapped ? GR_TEXTURECLAMP_WRAP : GR_TEXTURECLAMP_CLAMP);
  // The part with (s, t) in [0, 1] is the middle third; elsewhere clamp repeats its edge texels.
  const int inside = kSquareLeft + kPeriod;
  const long wrong = mismatches(square, [&](int x, int y) {
    return glm::ivec2(std::clamp(x, inside, inside + kPeriod - 1), std::clamp(y, inside, inside + kPeriod - 1));
  });
  const long total = kSquareSide * kSquareSide;
  figure.image = figures::compose({{texture_picture(), "THE 16X16 TEXTURE"},
                                   {figures::to_image(square, 1.0f), "CLAMPED, S AND T FROM -1 TO 2"}});
  figure.shows = "A 16x16 RGB 565 texture with coloured edge rows and columns on a square whose "
                 "(s, t) run from -1 to 2, GR_TEXTURECLAMP_CLAMP, point sampled: the texture once "
                 "in the middle, its edge texels smeared outwards.";
  figure.checks.push_back(check(
      "outside [0, 1] the clamped square repeats its edge texels (each pixel equals the nearest pixel of the [0, 1] part)",
      wrong * 100 <= total, format("%ld of %ld pixels differ", wrong, total)));
}

void figure_nguyen_11(Figure &figure, FigureFault fault) {
  const Words square = draw_square(fault == FigureFault::TextureModeSwapped ? GR_TEXTURECLAMP_CLAMP : GR_TEXTURECLAMP_WRAP);
  const int inside = kSquareLeft + kPeriod;
  const long wrong = mismatches(square, [&](int x, int y) {
    auto wrap = [&](int p) { return inside + ((p - inside) % kPeriod + kPeriod) % kPeriod; };
    return glm::ivec2(wrap(x), wrap(y));
  });
  const long total = kSquareSide * kSquareSide;
  figure.image = figures::compose({{texture_picture(), "THE 16X16 TEXTURE"},
                                   {figures::to_image(square, 1.0f), "TILED, S AND T FROM -1 TO 2"}});
  figure.shows = "The same square with GR_TEXTURECLAMP_WRAP: the texture three times across and "
                 "down.";
  figure.checks.push_back(check("tiling repeats the texture with period 1 in s and t (64 pixels here)",
                                wrong * 100 <= total,
                                format("%ld of %ld pixels differ from their copy one period away", wrong, total)));
}

namespace {

// Figure 12's scene: the floor in four large quads, as a game's floor would be, so receiver
// triangles reach far out of the light's view.
Scene coarse_floor_scene() {
  Scene scene = figures::article_scene();
  scene.objects[kFloor].mesh = make_plane(8.0f, 2);
  scene.objects[kFloor].mesh.set_color(glm::vec3(0.85f, 0.8f, 0.7f));
  return scene;
}

// The two light views of Figures 12 and 13: one whose border cuts the caster, the fitted one;
// a fault swaps either for the other.
void figure_views(FigureFault fault, glm::mat4 views[2]) {
  views[0] = fault == FigureFault::BorderIgnored ? glm::mat4(1.0f) : figures::border_cutting_view();
  views[1] = fault == FigureFault::NoCleanBorder ? figures::border_cutting_view() : glm::mat4(1.0f);
}

}  // namespace

void figure_nguyen_12(Figure &figure, FigureFault fault) {
  const Scene scene = coarse_floor_scene();
  ProjectedShadowOptions options;
  Words frames[2], masks[2];
  MaskErrors errors[2];
  glm::mat4 views[2];
  figure_views(fault, views);
  for (int i = 0; i < 2; ++i) {
    const Steps steps = run_steps(scene, options, views[i]);
    frames[i] = figures::read_back(scene.width, scene.height);
    render_shadow_mask(options, steps.frame);
    masks[i] = figures::read_back(scene.width, scene.height);
    errors[i] = against_truth(scene, masks[i]);
  }
  const auto false_shadow = [&](int i) {
    return static_cast<long>(std::lround(errors[i].false_shadow_interior *
                                         static_cast<double>(errors[i].receiver_pixels)));
  };
  figure.image = figures::compose({{figures::to_image(frames[0], kListing4Gamma), "CASTER CLIPPED: THE BUG"},
                                   {figures::to_image(frames[1], kListing4Gamma), "TWO-TEXEL CLEAN BORDER"}});
  figure.shows = "Left: the light's view narrowed and moved sideways so the texture's border "
                 "cuts through the fighter; clamp mode repeats the border's shadow texels over "
                 "the floor's large triangles that reach out of the view: streaks of shadow "
                 "where none belongs. Right: the fitted view with its clean border.";
  figure.checks.push_back(check(
      "the bug appears when the caster touches the texture border (false shadow away from the true edge) and disappears with a clean border",
      false_shadow(0) >= 300 && false_shadow(1) * 10 <= false_shadow(0),
      format("false shadow away from the edge: %ld pixels clipped, %ld with a clean border",
             false_shadow(0), false_shadow(1))));
}

void figure_nguyen_13(Figure &figure, FigureFault fault) {
  const Scene scene = coarse_floor_scene();
  glm::mat4 views[2];
  figure_views(fault, views);
  const Steps clipped = run_steps(scene, {}, views[0]);
  const Steps clean = run_steps(scene, {}, views[1]);
  const long touching = near_border(alpha_set(clipped.light_words), clipped.light_words.width, 1);
  const long clean_ring = near_border(alpha_set(clean.light_words), clean.light_words.width, 2);
  figure.image = figures::compose({{alpha_picture(clipped.light_words), "CLIPPED BY THE BORDER"},
                                   {alpha_picture(clean.light_words), "CLEAN BORDER"}});
  figure.shows = "The two shadow textures of Figure 12: the narrowed view cuts the fighter at the "
                 "texture's edge; the fitted view leaves every edge texel clear.";
  figure.checks.push_back(check("the clipped texture has silhouette texels on its outermost row or column",
                                touching > 0, format("%ld edge texels", touching)));
  figure.checks.push_back(check("the fitted texture has none within two texels of the edge", clean_ring == 0,
                                format("%ld texels within 2 of the edge", clean_ring)));
}

void figure_nguyen_14(Figure &figure, FigureFault fault) {
  const Scene scene = figures::article_scene();
  ProjectedShadowOptions options;
  const Steps steps = run_steps(scene, options, glm::mat4(1.0f), fault);
  if (steps.frame.jobs.empty()) {
    figure.checks.push_back(check("step 3 flagged receiver triangles", false, "no shadow job"));
    return;
  }
  const ShadowJob &job = steps.frame.jobs.front();
  const FrameGeometry geometry = project_scene(scene);
  Words frames[2];
  long changed[2] = {0, 0};
  const GrCmpFnc_t tests[2] = {fault == FigureFault::SecondPassLess ? GR_CMP_LESS : GR_CMP_LEQUAL, GR_CMP_LESS};
  for (int i = 0; i < 2; ++i) {
    render_scene(scene, geometry);
    const Words before = figures::read_back(scene.width, scene.height);
    grDepthBufferFunction(tests[i]);
    grDepthMask(FXFALSE);
    guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
    std::uint32_t hash = 2166136261u;
    for (const ShadowTriangle &t : job.receivers.triangles) {
      hash = (hash ^ 0x9E3779B9u) * 16777619u;  // a flat colour per triangle
      GrVertex v[3] = {t.v[0], t.v[1], t.v[2]};
      for (GrVertex &vertex : v) {
        vertex.r = static_cast<float>(64 + (hash & 0xBF));
        vertex.g = static_cast<float>(64 + ((hash >> 8) & 0xBF));
        vertex.b = static_cast<float>(64 + ((hash >> 16) & 0xBF));
      }
      guDrawTriangleWithClip(&v[0], &v[1], &v[2]);
    }
    frames[i] = figures::read_back(scene.width, scene.height);
    for (std::size_t p = 0; p < before.data.size(); ++p) changed[i] += before.data[p] != frames[i].data[p];
    set_scene_state();
  }
  figure.image = figures::compose({{figures::to_image(frames[0], kListing4Gamma), "SECOND PASS, LEQUAL"},
                                   {figures::to_image(frames[1], kListing4Gamma), "SECOND PASS, LESS"}});
  figure.shows = format("The %zu receiver triangles step 3 flagged (facing the light, inside its view, "
                        "seeing the caster) drawn again in flat colours over step 4's frame with "
                        "the same screen vertices: with LEQUAL they show, with LESS the depth test "
                        "rejects them.",
                        job.receivers.triangles.size());
  figure.checks.push_back(check(
      "the flagged triangles drawn a second time are visible with a less-or-equal depth test and rejected with less",
      changed[0] >= 2000 && changed[1] * 100 <= changed[0],
      format("%ld pixels changed with LEQUAL, %ld with LESS", changed[0], changed[1])));
}

void figure_nguyen_15(Figure &figure, FigureFault fault) {
  Scene scene = figures::article_scene();
  // Close on the shadow of the fighter's arms on the step, with a coarse texture.
  scene.camera.position = glm::vec3(1.6f, 2.2f, 0.6f);
  scene.camera.target = glm::vec3(1.7f, 0.0f, -0.9f);
  scene.camera.fov_degrees = 35.0f;
  TechniqueOptions alpha, chroma;
  alpha.projected.size = chroma.projected.size = 64;
  alpha.projected.bilinear = fault != FigureFault::PointSampled;
  // The figure shows coarse texels on purpose: the coarse-texel refusal is off.
  alpha.projected.largest_texel_footprint_px = chroma.projected.largest_texel_footprint_px = INFINITY;
  const Words unshadowed = figures::render_frame("none", {}, scene);
  const Words filtered = figures::render_frame("projected", alpha, scene);
  const Words keyed = figures::render_frame("projected-chroma", chroma, scene);
  // Pixels darkened by part of the full shadow (between a tenth and four fifths of it).
  auto partial = [&](const Words &frame) {
    long n = 0;
    for (std::size_t i = 0; i < frame.data.size(); ++i) {
      const double full = 170.0 / 255.0;
      const double d = figures::darkening(unshadowed.data[i], frame.data[i]);
      if (((unshadowed.data[i] >> 5) & 0x3F) >= 16 && d > 0.1 * full && d < 0.8 * full) ++n;
    }
    return n;
  };
  const long partial_alpha = partial(filtered), partial_chroma = partial(keyed);
  figure.image = figures::compose({{figures::to_image(keyed, kListing4Gamma), "CHROMA KEY"},
                                   {figures::to_image(filtered, kListing4Gamma), "ALPHA, BILINEAR"}});
  figure.shows = "A close view of the shadow on the step from a 64x64 texture. Left: the RGB 565 "
                 "texture with the background chroma-keyed away, point sampled: each pixel is "
                 "shadowed or not. Right: the ARGB_4444 alpha mask, bilinear: the edge ramps.";
  figure.checks.push_back(check(
      "alpha filtering gives many intermediate levels along the edge where the chroma key gives two (shadowed or not)",
      partial_alpha >= 300 && partial_chroma * 20 <= partial_alpha,
      format("%ld partly darkened pixels with alpha filtering, %ld with chroma key", partial_alpha,
             partial_chroma)));
}

}  // namespace gs
