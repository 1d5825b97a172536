// Step 5 of the projected shadow texture (the flagged triangles again with the shadow texture,
// a light at a time) and the shadow mask drawn the same way. Spaces: Glide screen (pixels, y
// down) of the camera; texture addresses are byte addresses in TMU0 memory.
#include "techniques/projected/projected_shadow.h"

#include <glideutl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace gs {
namespace {

// Step 5's state, also used by the mask pass with a different colour path.
void set_shadow_pass_state(FxU32 address, const ShadowTexture &texture,
                           const ProjectedShadowOptions &options) {
  GrTexInfo info = texture.info;
  grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  const GrTextureFilterMode_t filter = options.bilinear && !options.chroma_key
                                           ? GR_TEXTUREFILTER_BILINEAR
                                           : GR_TEXTUREFILTER_POINT_SAMPLED;
  grTexFilterMode(GR_TMU0, filter, filter);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  grHints(GR_HINT_STWHINT, options.projective ? GR_STWHINT_W_DIFF_TMU0 : 0);
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LEQUAL);
  grDepthMask(FXFALSE);
  grCullMode(GR_CULL_POSITIVE);
  if (options.chroma_key) {
    // Figure 15's alternative: texels of the background colour are rejected outright.
    grChromakeyValue(0);
    grChromakeyMode(GR_CHROMAKEY_ENABLE);
    grAlphaCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
  } else {
    grAlphaCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                   GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  }
}

// Step 5's depth levels, in W-buffer codes nearer than step 4's surfaces (grDepthBiasLevel; 4096
// codes an octave of w, on the Voodoo and in the shim). Each pixel is darkened once per light,
// however many of its casters' shadows overlap there: every pass that darkens also marks the
// pixels it darkened in the depth buffer (nearer), and the next shadow of the same light fails
// the depth test there (GR_CMP_LESS).
//   - Exact triangles (step 4's own screen vertices) darken and mark in one pass at kExactCodes:
//     another exact triangle at the same pixel gives the same depth, which is not less.
//   - Clipped polygons are cut along step 4's triangles and take their depth planes
//     (receiver_depth_planes.h), so they too lie on step 4's depth up to float rounding: they
//     darken at kClippedCodes, then mark kSealCodes nearer with colour writes off (a seal that
//     every later cover on the same surface, at kExactCodes or kClippedCodes, fails).
// Clipped polygons are drawn first, so an exact triangle after them fails on their seals. Each
// code more would let the shadow onto a nearer surface within that depth of the receiver.
// The first shadow to reach a pixel sets its darkening. With filtered edges, every shadow's
// core is drawn before any edge (core_alpha), so an edge inside another's core is the core's;
// where two soft edges cross, the first one drawn still decides (a few pixels along the crossing).
constexpr FxI16 kExactCodes = 1;
constexpr FxI16 kClippedCodes = 1;
constexpr FxI16 kSealCodes = kClippedCodes + 2;

// Which of a job's step-5 pieces to draw: its triangles, then its clipped polygons, one flag
// each; null for all of them.
using PieceFilter = std::vector<std::uint8_t>;

void draw_exact(const ReceiverCoords &receivers, const PieceFilter *only) {
  for (std::size_t i = 0; i < receivers.triangles.size(); ++i) {
    const ShadowTriangle &t = receivers.triangles[i];
    if (t.reaches_caster && (!only || (*only)[i])) guDrawTriangleWithClip(&t.v[0], &t.v[1], &t.v[2]);
  }
}

void draw_clipped(const ReceiverCoords &receivers, const PieceFilter *only) {
  const std::size_t first = receivers.triangles.size();
  for (std::size_t i = 0; i < receivers.clipped.size(); ++i)
    if (!only || (*only)[first + i]) draw_fan(receivers.clipped[i]);
}

// The screen box (Glide screen, pixels) of a piece step 5 draws.
struct ScreenBox {
  glm::vec2 min{INFINITY}, max{-INFINITY};
  void add(const GrVertex &v) {
    min = glm::min(min, glm::vec2(v.x, v.y)), max = glm::max(max, glm::vec2(v.x, v.y));
  }
  void add(const ScreenBox &box) { min = glm::min(min, box.min), max = glm::max(max, box.max); }
  bool empty() const { return !(min.x <= max.x && min.y <= max.y); }
};

// Per job, the screen boxes of its pieces in PieceFilter order (empty for a triangle step 5
// does not draw).
std::vector<ScreenBox> piece_boxes(const ReceiverCoords &receivers) {
  std::vector<ScreenBox> boxes;
  for (const ShadowTriangle &t : receivers.triangles) {
    boxes.emplace_back();
    if (t.reaches_caster)
      for (const GrVertex &v : t.v) boxes.back().add(v);
  }
  for (const std::vector<GrVertex> &polygon : receivers.clipped) {
    boxes.emplace_back();
    for (const GrVertex &v : polygon) boxes.back().add(v);
  }
  return boxes;
}

// Per job, which pieces share a screen cell with another job's pieces: only there can one
// shadow's soft edge lie in another's core. Empty when no piece does. Cells of at least 16
// pixels, at most 256 a side over the pieces' box, so the grid stays small whatever the
// guard band lets through.
std::vector<PieceFilter> shared_pieces(const std::vector<const ShadowJob *> &jobs) {
  std::vector<std::vector<ScreenBox>> boxes;
  ScreenBox all;
  for (const ShadowJob *job : jobs) {
    boxes.push_back(piece_boxes(job->receivers));
    for (const ScreenBox &box : boxes.back())
      if (!box.empty()) all.add(box);
  }
  if (all.empty()) return {};
  const float cell = std::max(16.0f, std::max(all.max.x - all.min.x, all.max.y - all.min.y) / 256.0f);
  const int columns = static_cast<int>((all.max.x - all.min.x) / cell) + 1;
  const int rows = static_cast<int>((all.max.y - all.min.y) / cell) + 1;
  auto cells_of = [&](const ScreenBox &box, auto &&visit) {
    // A pixel past the box's side: the shim snaps vertices to 1/16 pixel.
    const glm::ivec2 low(glm::max(box.min - 1.0f - all.min, 0.0f) / cell),
        high((box.max + 1.0f - all.min) / cell);
    for (int y = low.y; y <= std::min(high.y, rows - 1); ++y)
      for (int x = low.x; x <= std::min(high.x, columns - 1); ++x)
        visit(static_cast<std::size_t>(y) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(x));
  };
  constexpr int kNobody = -1, kSeveral = -2;
  std::vector<int> owner(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), kNobody);
  for (std::size_t j = 0; j < jobs.size(); ++j)
    for (const ScreenBox &box : boxes[j])
      if (!box.empty())
        cells_of(box, [&](std::size_t c) {
          owner[c] = owner[c] == kNobody || owner[c] == static_cast<int>(j) ? static_cast<int>(j) : kSeveral;
        });
  std::vector<PieceFilter> shared(jobs.size());
  bool any = false;
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    shared[j].assign(boxes[j].size(), 0);
    for (std::size_t i = 0; i < boxes[j].size(); ++i) {
      if (boxes[j][i].empty()) continue;
      cells_of(boxes[j][i], [&](std::size_t c) { shared[j][i] |= owner[c] == kSeveral; });
      any = any || shared[j][i];
    }
  }
  return any ? shared : std::vector<PieceFilter>{};
}

// The least alpha (texture alpha x iterated alpha, as the combine unit makes it) that only a
// pixel sampling fully covered texels gets, when the shadows of `jobs` have soft edges that
// another's core may hold: bilinear filtering and one iterated alpha for every pixel (the
// light's strength; distance alpha varies it per pixel). Covered texels have alpha 255
// (ARGB_4444's 15), and the Voodoo's 4-bit bilinear weights give any pixel with an uncovered
// texel among its four at most 255 x 15/16 = 239; the combine unit gives
// (texture x (iterated + 1)) >> 8. The threshold is taken halfway, at texture alpha 247.
std::optional<FxU8> core_alpha(const std::vector<const ShadowJob *> &jobs,
                               const ProjectedShadowOptions &options) {
  if (jobs.size() < 2 || !options.bilinear || options.chroma_key ||
      options.alpha != ShadowAlpha::Constant) {
    return std::nullopt;
  }
  std::optional<float> iterated;
  for (const ShadowJob *job : jobs) {
    const ReceiverCoords &receivers = job->receivers;
    if (!iterated && !receivers.triangles.empty()) iterated = receivers.triangles.front().v[0].a;
    if (!iterated && !receivers.clipped.empty() && !receivers.clipped.front().empty())
      iterated = receivers.clipped.front().front().a;
  }
  if (!iterated) return std::nullopt;
  const int factor = static_cast<int>(std::clamp(*iterated, 0.0f, 255.0f)) + 1;
  const int threshold = (247 * factor) >> 8, softest_edge = (239 * factor) >> 8;
  if (threshold <= softest_edge) return std::nullopt;  // too faint to tell a core from an edge
  return static_cast<FxU8>(threshold);
}

void restore_scene_state() {
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  grAlphaTestFunction(GR_CMP_ALWAYS);
  set_scene_state();
}

}  // namespace

void render_light_shadow_passes(const std::vector<const ShadowJob *> &jobs,
                                const ProjectedShadowOptions &options, const BindShadowTexture &bind) {
  // Black, at texture alpha x iterated alpha, over the lit scene; marks where the alpha passes
  // GR_CMP_GEQUAL `least_alpha` (at least 1).
  auto darken = [&](const ShadowJob &job, FxU8 least_alpha) {
    const std::optional<FxU32> address = bind(job);
    if (!address) return false;
    set_shadow_pass_state(*address, job.texture, options);
    grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ZERO,
                   GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                         GR_BLEND_ZERO);
    grAlphaTestFunction(GR_CMP_GEQUAL);
    grAlphaTestReferenceValue(least_alpha);
    grDepthBufferFunction(GR_CMP_LESS);
    return true;
  };
  // Every job's pieces that `only` keeps (all without it).
  auto draw_all = [&](FxU8 least_alpha, const std::vector<PieceFilter> *only) {
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      const PieceFilter *keep = only ? &(*only)[j] : nullptr;
      if (jobs[j]->receivers.clipped.empty() || !darken(*jobs[j], least_alpha)) continue;
      grDepthMask(FXFALSE);
      grDepthBiasLevel(-kClippedCodes);
      draw_clipped(jobs[j]->receivers, keep);
      grColorMask(FXFALSE, FXFALSE);  // the seal: depth only, where the cover darkened
      grDepthMask(FXTRUE);
      grDepthBiasLevel(-kSealCodes);
      draw_clipped(jobs[j]->receivers, keep);
      grColorMask(FXTRUE, FXFALSE);
    }
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      if (!darken(*jobs[j], least_alpha)) continue;
      grDepthMask(FXTRUE);
      grDepthBiasLevel(-kExactCodes);
      draw_exact(jobs[j]->receivers, only ? &(*only)[j] : nullptr);
    }
  };
  // The shadows' cores first where their filtered edges could meet another's core: otherwise
  // the shadow drawn first would darken its edge partly inside the other's core and mark it,
  // and the core would leave those pixels lighter than the rest of it (a bright seam). Only
  // the pieces that share screen cells with another shadow's are drawn twice.
  if (const std::optional<FxU8> core = core_alpha(jobs, options)) {
    const std::vector<PieceFilter> shared = shared_pieces(jobs);
    if (!shared.empty()) draw_all(*core, &shared);
  }
  draw_all(1, nullptr);
  grDepthBiasLevel(0);
  restore_scene_state();
}

// Step 5: the flagged triangles again with the shadow texture, for one shadow.
void render_shadow_pass(const ShadowJob &job, const ProjectedShadowOptions &options) {
  render_light_shadow_passes({&job}, options,
                             [](const ShadowJob &only) { return only.texture.address; });
}

namespace {

void draw_mask(const ProjectedShadowOptions &options, const ShadowFrame &frame,
               FxI16 exact_codes, FxI16 clipped_codes) {
  grDepthMask(FXFALSE);
  grBufferClear(0, 0, 0);  // colour only: the depth buffer keeps the frame's surfaces
  // Every texture where step 2 put it, unless step 5 had to load textures: then whatever the
  // passes since left in TMU memory is loaded again, each as its turn comes.
  ShadowTextureMemory memory = frame.textures;
  memory.forget_all();
  for (const ShadowJob &job : frame.jobs) {
    const std::optional<FxU32> address =
        frame.textures_loaded ? bind_shadow_texture(job, memory, frame.geometry)
                              : std::optional<FxU32>(job.texture.address);
    if (!address) continue;  // step 1 cannot draw it again (the shim's error says why)
    set_shadow_pass_state(*address, job.texture, options);
    // White where the pixel is in shadow as technique.h defines it: at least half of the
    // light's view of the point covered by the caster, i.e. the filtered texture alpha at least
    // 128 (the chroma-key variant samples one texel: the key rejects uncovered ones, and every
    // texel left is covered).
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_TEXTURE, FXFALSE);
    grConstantColorValue(0xFFFFFFFFu);
    grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
    if (options.chroma_key) {
      grAlphaTestFunction(GR_CMP_GREATER);
      grAlphaTestReferenceValue(0);
    } else {
      grAlphaCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                     GR_COMBINE_OTHER_TEXTURE, FXFALSE);  // the texture's alpha alone
      grAlphaTestFunction(GR_CMP_GEQUAL);
      grAlphaTestReferenceValue(128);
    }
    grDepthBiasLevel(-exact_codes);
    draw_exact(job.receivers, nullptr);
    grDepthBiasLevel(-clipped_codes);
    draw_clipped(job.receivers, nullptr);
    grDepthBiasLevel(0);
  }
  restore_scene_state();
}

}  // namespace

void render_shadow_mask(const ProjectedShadowOptions &options, const ShadowFrame &frame) {
  draw_mask(options, frame, kSealCodes + 8, kSealCodes + 8);
}

void render_shadow_mask(const Scene &scene, const ProjectedShadowOptions &options,
                        const ShadowFrame &frame) {
  grColorMask(FXFALSE, FXFALSE);
  render_scene(scene, frame.geometry);  // step 4's depth, without step 5's marks
  grColorMask(FXTRUE, FXFALSE);
  // LEQUAL at step 4's depth, as step 5 would find the surfaces without marks; the clipped
  // polygons a code nearer, for the rounding of their depth planes (kClippedCodes).
  draw_mask(options, frame, 0, 1);
}

}  // namespace gs
