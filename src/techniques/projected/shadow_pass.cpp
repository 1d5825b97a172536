// Step 5 of the projected shadow texture (the flagged triangles again with the shadow texture,
// a light at a time) and the shadow mask drawn the same way. Spaces: Glide screen (pixels, y
// down) of the camera; texture addresses are byte addresses in TMU0 memory.
#include "techniques/projected/projected_shadow.h"

#include <glideutl.h>

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
constexpr FxI16 kExactCodes = 1;
constexpr FxI16 kClippedCodes = 1;
constexpr FxI16 kSealCodes = kClippedCodes + 2;

void draw_exact(const ReceiverCoords &receivers) {
  for (const ShadowTriangle &t : receivers.triangles) {
    if (t.reaches_caster) guDrawTriangleWithClip(&t.v[0], &t.v[1], &t.v[2]);
  }
}

void draw_clipped(const ReceiverCoords &receivers) {
  for (const std::vector<GrVertex> &polygon : receivers.clipped) draw_fan(polygon);
}

void restore_scene_state() {
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  grAlphaTestFunction(GR_CMP_ALWAYS);
  set_scene_state();
}

}  // namespace

void render_light_shadow_passes(const std::vector<const ShadowJob *> &jobs,
                                const ProjectedShadowOptions &options, const BindShadowTexture &bind) {
  // Black, at texture alpha x iterated alpha, over the lit scene; marks where alpha > 0.
  auto darken = [&](const ShadowJob &job) {
    const std::optional<FxU32> address = bind(job);
    if (!address) return false;
    set_shadow_pass_state(*address, job.texture, options);
    grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ZERO,
                   GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                         GR_BLEND_ZERO);
    grAlphaTestFunction(GR_CMP_GREATER);
    grAlphaTestReferenceValue(0);
    grDepthBufferFunction(GR_CMP_LESS);
    return true;
  };
  for (const ShadowJob *job : jobs) {
    if (job->receivers.clipped.empty() || !darken(*job)) continue;
    grDepthMask(FXFALSE);
    grDepthBiasLevel(-kClippedCodes);
    draw_clipped(job->receivers);
    grColorMask(FXFALSE, FXFALSE);  // the seal: depth only, where the cover darkened
    grDepthMask(FXTRUE);
    grDepthBiasLevel(-kSealCodes);
    draw_clipped(job->receivers);
    grColorMask(FXTRUE, FXFALSE);
  }
  for (const ShadowJob *job : jobs) {
    if (!darken(*job)) continue;
    grDepthMask(FXTRUE);
    grDepthBiasLevel(-kExactCodes);
    draw_exact(job->receivers);
  }
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
    draw_exact(job.receivers);
    grDepthBiasLevel(-clipped_codes);
    draw_clipped(job.receivers);
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
