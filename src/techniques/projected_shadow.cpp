// The projected shadow texture in the article's order: step 2's texture, step 5's pass and the
// frame that runs all five (render_projected_shadows), and the shadow mask. Step 1's light view
// is fitted in light_view_fit.cpp and its flat render is caster_from_light.cpp, step 3 is
// receiver_coords.cpp, step 4 scene_pass.cpp. Spaces: light view and light clip (step 1); Glide screen (pixels, y down)
// for the light's size x size view in step 1 and the camera in steps 4-5.
#include "techniques/projected_shadow.h"
#include "techniques/step_clock.h"

#include "techniques/caster_surface_from_light.h"
#include "techniques/pierced_receivers.h"
#include "techniques/receiver_layers.h"

#include <glide_shim.h>
#include <glideutl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gs {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

// Step 2: the region read back and downloaded as ARGB_4444 (or already in texture memory).
ShadowTexture make_shadow_texture(const LightView &view, const ProjectedShadowOptions &options,
                                  FxU32 texture_address) {
  ShadowTexture texture;
  texture.address = texture_address;
  texture.info.smallLod = texture.info.largeLod = shadow_lod(view.size);
  texture.info.aspectRatio = GR_ASPECT_1x1;
  // The same 16-bit words, read as ARGB_4444: alpha is the top nibble of the red field.
  // The chroma-key variant reads them as the colour they were drawn in.
  texture.info.format = options.chroma_key ? GR_TEXFMT_RGB_565 : GR_TEXFMT_ARGB_4444;
  if (view.direct_path) return texture;  // step 1 already wrote texture memory

  const auto side = static_cast<FxU32>(view.size);
  std::vector<FxU16> shadow_bitmap(static_cast<std::size_t>(side) * side);  // system memory
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, side, side, side * 2, shadow_bitmap.data());
  texture.info.data = shadow_bitmap.data();
  grTexDownloadMipMap(GR_TMU0, texture_address, GR_MIPMAPLEVELMASK_BOTH, &texture.info);
  texture.info.data = nullptr;
  return texture;
}

// Step 3 is compute_receiver_coords (receiver_coords.cpp), step 4 render_scene (scene_pass.cpp).

namespace {

// Step 5's state, also used by the mask pass with a different colour path.
void set_shadow_pass_state(const ShadowTexture &texture, const ProjectedShadowOptions &options) {
  GrTexInfo info = texture.info;
  grTexSource(GR_TMU0, texture.address, GR_MIPMAPLEVELMASK_BOTH, &info);
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

// Step 5 for the shadows of one light, in order, each pixel darkened once (the depth levels
// above). Leaves marks in the depth buffer, up to kSealCodes nearer than step 4's surfaces.
void render_light_shadow_passes(const std::vector<const ShadowJob *> &jobs,
                                const ProjectedShadowOptions &options) {
  // Black, at texture alpha x iterated alpha, over the lit scene; marks where alpha > 0.
  auto darken = [&](const ShadowJob &job) {
    set_shadow_pass_state(job.texture, options);
    grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ZERO,
                   GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                         GR_BLEND_ZERO);
    grAlphaTestFunction(GR_CMP_GREATER);
    grAlphaTestReferenceValue(0);
    grDepthBufferFunction(GR_CMP_LESS);
  };
  for (const ShadowJob *job : jobs) {
    if (job->receivers.clipped.empty()) continue;
    darken(*job);
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
    darken(*job);
    grDepthMask(FXTRUE);
    grDepthBiasLevel(-kExactCodes);
    draw_exact(job->receivers);
  }
  grDepthBiasLevel(0);
  restore_scene_state();
}

}  // namespace

// Step 5: the flagged triangles again with the shadow texture, for one shadow.
void render_shadow_pass(const ShadowJob &job, const ProjectedShadowOptions &options) {
  render_light_shadow_passes({&job}, options);
}

ShadowFrame render_projected_shadows(const Scene &scene, const ProjectedShadowOptions &options,
                                     bool synchronous) {
  ShadowFrame result;
  const auto frame_start = Clock::now();
  auto finish_step = [&](int step, Clock::time_point start) {
    if (synchronous) grSstIdle();
    result.times.ms[step] += elapsed_ms(start);
  };
  FrameGeometry frame = project_scene(scene);
  grRenderBuffer(GR_BUFFER_BACKBUFFER);
  FxU32 next_address = grTexMinAddress(GR_TMU0);
  const bool point_sampled = options.chroma_key || !options.bilinear;
  const float largest_footprint =
      options.largest_texel_footprint_px > 0.0f ? options.largest_texel_footprint_px
      : point_sampled                           ? kLargestPointSampledFootprintPx
                                                : kLargestTexelFootprintPx;
  // The most pixels the estimated error along the frame's shadow edges may reach
  // (shadow_edge_error.h), from the receivers' pixels once a shadow has an estimate; off with
  // the footprint check.
  std::optional<float> largest_edge_error;
  if (std::isinf(options.largest_texel_footprint_px)) largest_edge_error = INFINITY;
  float edge_error_taken = 0.0f;  // by the shadows cast so far
  auto add_note = [&](const LightView &view) {  // once per frame
    if (!view.note.empty() &&
        std::find(result.warnings.begin(), result.warnings.end(), view.note) == result.warnings.end()) {
      result.warnings.push_back(view.note);
    }
  };
  for (std::size_t light = 0; light < scene.lights.size(); ++light) {
    if (scene.lights[light].is_projector()) continue;  // slides cast no shadows
    for (std::size_t caster = 0; caster < scene.objects.size(); ++caster) {
      if (!scene.objects[caster].casts_shadow) continue;
      auto start = Clock::now();
      const LightView fitted = fit_light_view(scene, caster, light, options);  // 1
      result.times.ms[0] += elapsed_ms(start);
      if (!fitted.usable) {
        if (!fitted.outside_beam) result.errors.push_back(fitted.problem);
        continue;
      }
      // This caster's textures (a map above 256 is several, and one more per planar receiver it
      // reaches through); kept only if every one's texels are fine enough for the screen where
      // the shadow falls.
      std::vector<ShadowJob> caster_jobs;
      const FxU32 caster_address = next_address;
      // The caster's textures for the receivers marked in `receivers`; for a `pierced` one,
      // clipped to the light's side of its plane (world) or masked by its surface.
      // Step 1's cover of each texture's view (in split_into_textures' order) as fitted, the
      // same for the caster's texture for the other receivers and for each non-planar receiver
      // it reaches through (the mask changes only W and adds the cut to the silhouette), so it
      // is made once per caster.
      std::vector<std::optional<std::pair<LightView, CasterDraw>>> shared_covers;
      CasterSurfacesFromLight surfaces(scene.objects[caster]);  // step 3's, shared the same way
      auto cast = [&](const std::vector<bool> &receivers, const PiercedReceiver *pierced) {
        const std::vector<LightView> parts = split_into_textures(fitted);
        shared_covers.resize(parts.size());
        for (std::size_t index = 0; index < parts.size(); ++index) {
          const LightView &part = parts[index];
          // Each texture takes its own TMU memory; when 2 MB run out, the rest cast nothing.
          GrTexInfo needed{shadow_lod(part.size), shadow_lod(part.size), GR_ASPECT_1x1,
                           GR_TEXFMT_ARGB_4444, nullptr};
          if (next_address + grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &needed) >
              grTexMaxAddress(GR_TMU0) + 8) {
            result.errors.push_back("TMU memory is full: '" + scene.objects[caster].name +
                                    "' casts no shadow from light " + std::to_string(light));
            return;
          }
          ShadowJob job;
          job.caster = caster;
          job.light = light;
          job.view = part;
          SurfaceMask mask;
          if (pierced && pierced->planar) {
            // A world plane as a light-view plane: the inverse transpose of the view matrix.
            const glm::vec4 plane = glm::transpose(glm::inverse(part.view)) * pierced->plane;
            job.view.caster_planes.push_back(plane);
            job.view.edge_planes.push_back(plane);
          } else if (pierced) {
            mask = {&frame.objects[pierced->receiver], &pierced->caster_crossing};
          }
          const SurfaceMask *masked = mask.receiver ? &mask : nullptr;
          auto step_start = Clock::now();
          CasterDraw draw;  // 1
          if (pierced && pierced->planar) {
            draw = cover_caster_from_light(scene, caster, job.view, options);
          } else {
            std::optional<std::pair<LightView, CasterDraw>> &shared = shared_covers[index];
            if (!shared) {
              shared.emplace(part, CasterDraw{});
              shared->second = cover_caster_from_light(scene, caster, shared->first, options);
            }
            job.view = shared->first;
            draw = shared->second;
            if (masked) mask_caster_cover(scene, caster, job.view, *masked, draw);
          }
          finish_step(0, step_start);
          // Step 3 needs only step 1's cover, not its pixels: a texture whose receivers give step
          // 5 nothing to draw and the footprint check nothing to measure changes no byte of the
          // frame, so it is neither drawn nor read back (the other fighter, in front of a
          // fighter's shadow, receives nothing from it in most frames of the demo).
          step_start = Clock::now();
          job.receivers = compute_receiver_coords(scene, frame, caster, scene.lights[light],
                                                  job.view, options, &receivers, &surfaces);  // 3
          finish_step(2, step_start);
          if (job.receivers.clipped.empty() && job.receivers.footprints.empty() &&
              std::none_of(job.receivers.triangles.begin(), job.receivers.triangles.end(),
                           [](const ShadowTriangle &t) { return t.reaches_caster; })) {
            add_note(job.view);
            continue;
          }
          step_start = Clock::now();
          draw_caster_from_light(scene, job.view, next_address, masked, draw);  // 1
          finish_step(0, step_start);
          if (!job.view.usable) {
            result.errors.push_back(job.view.problem);
            continue;
          }
          add_note(job.view);
          step_start = Clock::now();
          job.texture = make_shadow_texture(job.view, options, next_address);  // 2
          finish_step(1, step_start);
          GrTexInfo info = job.texture.info;
          next_address += grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &info);
          caster_jobs.push_back(std::move(job));
        }
      };
      start = Clock::now();
      std::vector<PiercedReceiver> pierced =
          pierced_receivers(scene, frame, caster, scene.lights[light].position);
      // Receivers hiding part of the caster from the light get the texture masked by their
      // surface; one holding a caster part between two of its layers gets no shadow, by name.
      const ReceiverLayers layers = receiver_layers(scene, frame, caster, fitted, pierced);
      for (std::size_t r : layers.hiding) {
        if (std::none_of(pierced.begin(), pierced.end(),
                         [r](const PiercedReceiver &p) { return p.receiver == r; })) {
          PiercedReceiver masked;
          masked.receiver = r;
          masked.planar = false;
          masked.casts = true;
          masked.caster_crossing.assign(caster_mesh(scene.objects[caster]).triangles.size(), 0);
          pierced.push_back(std::move(masked));
        }
      }
      for (std::size_t r : layers.between) {
        result.errors.push_back(receiver_layers_error(scene, light, caster, r));
        pierced.erase(std::remove_if(pierced.begin(), pierced.end(),
                                     [r](const PiercedReceiver &p) { return p.receiver == r; }),
                      pierced.end());
      }
      result.times.ms[0] += elapsed_ms(start);
      std::vector<bool> receivers(scene.objects.size(), true);
      for (const PiercedReceiver &p : pierced) receivers[p.receiver] = false;
      for (std::size_t r : layers.between) receivers[r] = false;
      bool others = false;  // a receiver left for the whole caster's texture
      for (std::size_t r = 0; r < scene.objects.size(); ++r) {
        others = others || (receivers[r] && r != caster && scene.objects[r].receives_shadow);
      }
      if (others) cast(receivers, nullptr);
      for (const PiercedReceiver &p : pierced) {
        if (!p.casts) continue;  // nothing of the caster on the light's side: no shadow on it
        std::vector<bool> only(scene.objects.size(), false);
        only[p.receiver] = true;
        cast(only, &p);
      }
      std::vector<FootprintSample> samples;
      for (const ShadowJob &job : caster_jobs) {
        samples.insert(samples.end(), job.receivers.footprints.begin(), job.receivers.footprints.end());
      }
      const FootprintSample coarsest = shadow_footprint(
          std::move(samples),
          kFootprintIgnoredScreenShare * static_cast<float>(scene.width) * static_cast<float>(scene.height));
      result.texel_footprint_px = std::max(result.texel_footprint_px, coarsest.pixels_per_texel);
      if (coarsest.pixels_per_texel > largest_footprint) {
        result.errors.push_back(texel_footprint_error(scene, light, caster, coarsest.receiver,
                                                      coarsest.pixels_per_texel, largest_footprint,
                                                      fitted.size, 512));  // its largest size
        next_address = caster_address;  // its textures are not used
        continue;
      }
      // The error along the shadow's edges, over all its textures (shadow_edge_error.h).
      EdgeErrorEstimate edge_error;
      std::size_t edge_error_receiver = 0;
      float edge_error_receiver_pixels = -1.0f;
      for (const ShadowJob &job : caster_jobs) {
        edge_error.add(job.receivers.edge_error);
        if (job.receivers.edge_error_receiver_pixels > edge_error_receiver_pixels) {
          edge_error_receiver = job.receivers.edge_error_receiver;
          edge_error_receiver_pixels = job.receivers.edge_error_receiver_pixels;
        }
      }
      // The frame's budget is shared: casters take it in the scene's order, and one that would
      // overdraw it is refused.
      EdgeErrorEstimate within_budget = edge_error;
      for (float &pixels : within_budget.pixels) pixels += edge_error_taken;
      if (!largest_edge_error && edge_error.pixels[0] > 0.0f) {
        largest_edge_error = kEdgeErrorReceiverShare * receiver_screen_pixels(scene, frame);
      }
      if (largest_edge_error && within_budget.pixels[0] > *largest_edge_error) {
        result.errors.push_back(shadow_edge_error_message(
            scene, light, caster, edge_error_receiver, edge_error_taken, within_budget,
            *largest_edge_error, fitted.size, 512));  // its largest size
        next_address = caster_address;
        continue;
      }
      edge_error_taken += edge_error.pixels[0];
      for (ShadowJob &job : caster_jobs) result.jobs.push_back(std::move(job));
    }
  }
  auto start = Clock::now();
  render_scene(scene, frame);  // 4
  finish_step(3, start);
  start = Clock::now();
  // 5, a light at a time (jobs are in light order). Between lights the depth buffer gets step
  // 4's surfaces back (a depth-only scene pass), so each light's marks start from them.
  std::vector<const ShadowJob *> same_light;
  for (std::size_t j = 0; j < result.jobs.size(); ++j) {
    same_light.push_back(&result.jobs[j]);
    if (j + 1 < result.jobs.size() && result.jobs[j + 1].light == result.jobs[j].light) continue;
    render_light_shadow_passes(same_light, options);
    same_light.clear();
    if (j + 1 < result.jobs.size()) {
      grColorMask(FXFALSE, FXFALSE);
      render_scene(scene, frame);
      grColorMask(FXTRUE, FXFALSE);
    }
  }
  finish_step(4, start);
  result.times.total_ms = elapsed_ms(frame_start);
  result.geometry = std::move(frame);
  // Errors are warnings too, so that a caller showing only warnings still shows them.
  result.warnings.insert(result.warnings.begin(), result.errors.begin(), result.errors.end());
  return result;
}

namespace {

void draw_mask(const ProjectedShadowOptions &options, const ShadowFrame &frame,
               FxI16 exact_codes, FxI16 clipped_codes) {
  grDepthMask(FXFALSE);
  grBufferClear(0, 0, 0);  // colour only: the depth buffer keeps the frame's surfaces
  for (const ShadowJob &job : frame.jobs) {
    set_shadow_pass_state(job.texture, options);
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
