// The projected shadow texture in the article's order: the frame that runs all five steps
// (render_projected_shadows). Step 1's light view is fitted in light_view_fit.cpp and its flat
// render is caster_from_light.cpp, step 2 is shadow_textures.cpp (with the textures' TMU
// memory, shadow_texture_memory.h), step 3 receiver_coords.cpp, step 4 scene_pass.cpp, step 5
// and the shadow mask shadow_pass.cpp. Spaces: light view and light clip (step 1); Glide screen
// (pixels, y down) for the light's size x size view in step 1 and the camera in steps 4-5.
#include "techniques/projected/projected_shadow.h"
#include "techniques/step_clock.h"

#include "techniques/projected/caster_surface_from_light.h"
#include "techniques/projected/contact_strips.h"
#include "techniques/projected/pierced_receivers.h"
#include "techniques/projected/hidden_layers.h"
#include "techniques/projected/receiver_layers.h"
#include "techniques/light_passes/slide_projector.h"

#include <glide_shim.h>

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
  // TMU0 memory from its lowest texture address to its end (grTexMaxAddress leaves 8 bytes).
  result.textures = ShadowTextureMemory(grTexMinAddress(GR_TMU0), grTexMaxAddress(GR_TMU0) + 8);
  std::size_t texture_ids = 0;
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
  // Every shadow's so far, cast or refused, at each doubling of its size: a refusal names a
  // larger size only where its error fits beside them all, since they may all be cast there.
  EdgeErrorEstimate edge_error_of_all;
  // Step 2 of the texture step 1 drew last on the LFB path, whose drawing the renderer was left
  // to do (glideShimFlush) while the program goes on with the next texture's steps 1 and 3 and
  // the next caster's fitting: the read-back then waits only for what is left of it. Done before
  // anything else draws (the next step 1, which clears the same corner of the back buffer, and
  // step 4). A texture of a caster refused meanwhile is read only while its jobs are still at
  // hand (no other caster has begun since), and then for nothing: no pass draws with it.
  struct PendingRead {
    std::size_t id;              // the texture's (ShadowTexture::id)
    std::optional<FxU32> placed;  // its TMU address, when step 2 placed it
  };
  std::optional<PendingRead> pending;
  std::vector<ShadowJob> caster_jobs;  // the caster's textures (below)
  auto read_pending = [&] {
    if (!pending) return;
    const std::size_t id = pending->id;
    auto has_id = [id](const ShadowJob &job) { return job.texture.id == id; };
    ShadowJob *job = nullptr;
    for (std::vector<ShadowJob> *jobs : {&result.jobs, &caster_jobs}) {
      const auto found = std::find_if(jobs->begin(), jobs->end(), has_id);
      if (!job && found != jobs->end()) job = &*found;
    }
    if (job) {
      const auto step_start = Clock::now();
      job->texture = pending->placed ? make_shadow_texture(job->view, options, *pending->placed)  // 2
                                     : read_shadow_texture(job->view, options);
      job->texture.id = id;
      finish_step(1, step_start);
    }
    pending.reset();
  };
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
      // The size the caster's shadow is tried at: the options', then (grow_to_accepted) the
      // smallest larger one the estimates accept after a refusal as too coarse, which is then
      // checked again the same way. A refused attempt leaves nothing behind in the frame.
      ProjectedShadowOptions sized = options;
      std::string grown_from;  // the first attempt's refusal's reason, for the note
      for (;;) {
        const std::size_t errors_before = result.errors.size();
        const std::size_t warnings_before = result.warnings.size();
        const float footprint_before = result.texel_footprint_px;
        const EdgeErrorEstimate of_all_before = edge_error_of_all;
        auto start = Clock::now();
        const LightView fitted = fit_light_view(scene, caster, light, sized);  // 1
        result.times.ms[0] += elapsed_ms(start);
        if (!fitted.usable) {
          if (!fitted.outside_beam) result.errors.push_back(fitted.problem);
          break;
        }
        const float caster_back = farthest_depth(scene.objects[caster], fitted.view);
        // The caster's plane (world, positive on the light's side) when it is flat, which
        // steps 1 and 3 ask about every texture.
        const std::optional<glm::vec4> caster_plane =
            planar_caster(scene.objects[caster], scene.lights[light].position);
        // This caster's textures (a map above 256 is several, and one more per planar receiver it
        // reaches through); kept only if every one's texels are fine enough for the screen where
        // the shadow falls.
        caster_jobs.clear();
        const FxU32 caster_mark = result.textures.mark();
        // The caster's textures for the receivers marked in `receivers`; for a `pierced` one,
        // clipped to the light's side of its plane (world) or masked by its surface.
        // Step 1's cover of each texture's view (in split_into_textures' order) as fitted, the
        // same for the caster's texture for the other receivers and for each non-planar receiver
        // it reaches through (the mask changes only W and adds the cut to the silhouette), so it
        // is made once per caster.
        std::vector<std::optional<std::pair<LightView, CasterDraw>>> shared_covers;
        CasterSurfacesFromLight surfaces(scene.objects[caster]);  // step 3's, shared the same way
        // With `farthest`, the non-planar `pierced` receiver's mask is its farthest surface
        // (SurfaceMask::farthest). Returns whether a texture's band -1 left a triangle to band -2.
        const std::vector<std::uint8_t> *over_buried = nullptr;  // the pierced receiver's
        auto cast = [&](const std::vector<bool> &receivers, const std::vector<signed char> &bands,
                        const PiercedReceiver *pierced, bool farthest) {
          bool hidden_left = false;
          const std::vector<LightView> parts = split_into_textures(fitted);
          shared_covers.resize(parts.size());
          for (std::size_t index = 0; index < parts.size(); ++index) {
            const LightView &part = parts[index];
            // Each texture takes its own TMU memory while it fits; the rest are loaded in turn as
            // step 5 draws with them (shadow_texture_memory.h). One larger than the memory cannot be.
            GrTexInfo needed{shadow_lod(part.size), shadow_lod(part.size), GR_ASPECT_1x1,
                             GR_TEXFMT_ARGB_4444, nullptr};
            const FxU32 bytes = grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &needed);
            // A hidden pass (`farthest`) splits its triangles by layer when a middle layer may be in
            // the shadow (hidden_layers.h): band -2 keeps the twice hidden ones, and band -3 takes
            // the once hidden ones, masked by the hidden triangles' own nearest surface.
            std::vector<std::uint8_t> classes;
            if (farthest) classes = hidden_layers(frame.objects[pierced->receiver], part, surfaces);
            std::vector<signed char> middle_bands;
            if (!classes.empty()) middle_bands = bands, middle_bands[pierced->receiver] = -3;
            for (int pass = 0; pass < (classes.empty() ? 1 : 2); ++pass) {
              const bool middle = pass == 1;
              if (!result.textures.can_hold(bytes)) {
                result.errors.push_back("TMU memory is too small: '" + scene.objects[caster].name +
                                        "' casts no shadow from light " + std::to_string(light) +
                                        ", its " + std::to_string(part.size) + "x" +
                                        std::to_string(part.size) + " texture needs " +
                                        std::to_string(bytes) + " bytes");
                return hidden_left;
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
                mask = {&frame.objects[pierced->receiver], &pierced->caster_crossing,
                        farthest && !middle, middle ? &classes : nullptr};
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
                if (masked) {
                  job.view.contact_strips =
                      contact_strips(job.view, pierced->contacts, scene.objects[caster], draw.closed,
                                     frame.objects[pierced->receiver], scene.camera.position,
                                     frame.view_projection);
                }
              }
              finish_step(0, step_start);
              // Step 3 needs only step 1's cover, not its pixels: a texture whose receivers give step
              // 5 nothing to draw and the footprint check nothing to measure changes no byte of the
              // frame, so it is neither drawn nor read back (the other fighter, in front of a
              // fighter's shadow, receives nothing from it in most frames of the demo).
              step_start = Clock::now();
              job.receivers = compute_receiver_coords(scene, frame, caster, scene.lights[light],
                                                      job.view, options, &receivers,
                                                      middle ? &middle_bands : &bands, caster_back,
                                                      &surfaces, classes.empty() ? nullptr : &classes,
                                                      over_buried, &caster_plane);  // 3
              finish_step(2, step_start);
              hidden_left = hidden_left || job.receivers.hidden_left;
              if (job.receivers.clipped.empty() && job.receivers.footprints.empty() &&
                  std::none_of(job.receivers.triangles.begin(), job.receivers.triangles.end(),
                               [](const ShadowTriangle &t) { return t.reaches_caster; })) {
                add_note(job.view);
                continue;
              }
              // A texture left unplaced is drawn on the direct path only when step 5 loads it.
              const std::size_t id = texture_ids++;
              const std::optional<FxU32> placed = result.textures.place(id, bytes);
              const bool drawn_now = placed || !job.view.direct_path;
              if (drawn_now) read_pending();
              step_start = Clock::now();
              if (job.view.direct_path) grGlideGetState(&job.step1_state);
              if (drawn_now) {
                draw_caster_from_light(scene, job.view, placed.value_or(0), masked, draw);  // 1
                if (!job.view.direct_path) glideShimFlush();
              }
              finish_step(0, step_start);
              if (!job.view.usable) {
                if (placed) result.textures.release_from(*placed);
                result.errors.push_back(job.view.problem);
                continue;
              }
              add_note(job.view);
              if (job.view.direct_path) {
                step_start = Clock::now();
                job.texture = placed ? make_shadow_texture(job.view, options, *placed)  // 2
                                     : read_shadow_texture(job.view, options);
                finish_step(1, step_start);
              } else {
                pending = PendingRead{id, placed};  // 2, read_pending
              }
              job.texture.id = id;
              job.mask_farthest = masked && farthest && !middle;
              if (job.view.direct_path) {
                job.draw = std::move(draw);
                if (masked) job.mask_receiver = pierced->receiver;
                if (masked && middle) job.mask_triangles = classes;
              }
              caster_jobs.push_back(std::move(job));
            }
          }
          return hidden_left;
        };
        start = Clock::now();
        std::vector<PiercedReceiver> pierced =
            pierced_receivers(scene, frame, caster, scene.lights[light].position, caster_plane);
        // Receivers hiding part of the caster from the light get the texture masked by their
        // surface. One holding a caster part between two of its layers takes it too when it casts
        // nothing: its nearer layer the texture masked by its nearest surface, the farther layer
        // that its own surface hides the one masked by its farthest (step 3's depth band -2). One
        // that casts gets no shadow, by name (a pole over a ridge of a floor that casts: 0.111%
        // interior error served with the two textures).
        const ReceiverLayers layers =
            receiver_layers(scene, frame, caster, fitted, pierced, caster_plane);
        std::vector<std::size_t> refused;
        for (std::size_t r : layers.between) {
          if (scene.objects[r].casts_shadow) refused.push_back(r);
        }
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
        for (std::size_t r : refused) {
          result.errors.push_back(receiver_layers_error(scene, light, caster, r));
          pierced.erase(std::remove_if(pierced.begin(), pierced.end(),
                                       [r](const PiercedReceiver &p) { return p.receiver == r; }),
                        pierced.end());
        }
        result.times.ms[0] += elapsed_ms(start);
        std::vector<bool> receivers(scene.objects.size(), true);
        // A receiver masking the caster takes the masked texture only nearer the light than the
        // caster's farthest vertex (light view depth), and the whole caster's beyond it: there
        // every caster point on the light's ray is in front of it, buried or hidden or not, and
        // shadows it (a foot in a dune shadows the dune's far slope).
        std::vector<signed char> bands(scene.objects.size(), 0);
        for (const PiercedReceiver &p : pierced) {
          receivers[p.receiver] = !p.planar;
          if (!p.planar) bands[p.receiver] = 1;
        }
        for (std::size_t r : refused) receivers[r] = false;
        bool others = false;  // a receiver left for the whole caster's texture
        for (std::size_t r = 0; r < scene.objects.size(); ++r) {
          others = others || (receivers[r] && r != caster && scene.objects[r].receives_shadow);
        }
        if (others) cast(receivers, bands, nullptr, false);
        for (const PiercedReceiver &p : pierced) {
          std::vector<bool> only(scene.objects.size(), false);
          only[p.receiver] = true;
          std::vector<signed char> near(scene.objects.size(), 0);
          if (!p.planar) near[p.receiver] = -1;
          // Band -1's triangles among those the receiver's surface hides in part: the ones the
          // caster passes through, or in front of a caster part with a farther layer behind.
          std::vector<std::uint8_t> front_marks = p.receiver_crossing;
          for (const auto &[r, marks] : layers.over_buried) {
            if (r != p.receiver) continue;
            front_marks.resize(marks.size(), 0);
            for (std::size_t k = 0; k < marks.size(); ++k) front_marks[k] |= marks[k];
          }
          over_buried = front_marks.empty() ? nullptr : &front_marks;
          // Nothing of the caster on the light's side of the receiver's nearest surface: no
          // shadow on that surface.
          const bool hidden_left = p.casts && cast(only, near, &p, false);
          // The receiver's parts its own surface hides from the light, masked by its farthest
          // light-facing surface (step 3's band -2), when band -1 left some; with a middle layer
          // that may be shadowed, that layer masked by the hidden parts' nearest surface (-3).
          if (!p.planar && (hidden_left || !p.casts)) {
            near[p.receiver] = -2;
            cast(only, near, &p, true);
          }
        }
        over_buried = nullptr;
        std::vector<FootprintSample> samples;
        for (const ShadowJob &job : caster_jobs) {
          samples.insert(samples.end(), job.receivers.footprints.begin(), job.receivers.footprints.end());
        }
        const FootprintSample coarsest = shadow_footprint(
            std::move(samples),
            kFootprintIgnoredScreenShare * static_cast<float>(scene.width * scene.height));
        result.texel_footprint_px = std::max(result.texel_footprint_px, coarsest.pixels_per_texel);
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
        EdgeErrorEstimate at_larger_sizes = edge_error;
        at_larger_sizes.add(edge_error_of_all);
        edge_error_of_all.add(edge_error);
        const bool too_coarse = coarsest.pixels_per_texel > largest_footprint;
        if (too_coarse || (largest_edge_error && within_budget.pixels[0] > *largest_edge_error)) {
          constexpr int kLargestSize = 512;  // four 256x256 textures
          const AcceptedSize accepted =
              smallest_accepted_size(fitted.size, kLargestSize, coarsest.pixels_per_texel,
                                     largest_footprint, at_larger_sizes, largest_edge_error);
          const std::string reason =
              too_coarse ? texel_footprint_reason(scene, light, caster, coarsest.receiver,
                                                  coarsest.pixels_per_texel, largest_footprint,
                                                  fitted.size, accepted_size_words(accepted))
                         : shadow_edge_error_reason(scene, light, caster, edge_error_receiver,
                                                    edge_error_taken, within_budget,
                                                    *largest_edge_error, fitted.size, accepted);
          result.textures.release_from(caster_mark);  // its textures are not used
          if (options.grow_to_accepted && accepted.size > fitted.size) {
            result.errors.resize(errors_before);
            result.warnings.resize(warnings_before);
            result.texel_footprint_px = footprint_before;
            edge_error_of_all = of_all_before;
            if (grown_from.empty()) grown_from = reason;
            sized.size = accepted.size, sized.auto_size = false;
            continue;
          }
          result.errors.push_back(reason + "; " + kCastsNoShadow);
          break;
        }
        if (!grown_from.empty()) {
          result.warnings.push_back(grown_shadow_note(grown_from, fitted.size));
        }
        result.sizes.push_back({light, caster, fitted.size});
        edge_error_taken += edge_error.pixels[0];
        for (ShadowJob &job : caster_jobs) result.jobs.push_back(std::move(job));
        caster_jobs.clear();  // what is left of them is not a texture to read (read_pending)
        break;
      }
    }
  }
  // What TMU memory holds as step 5 goes: step 2's textures, but for the slide textures' memory
  // after each scene pass, and what step 5 loads.
  ShadowTextureMemory memory = result.textures;
  auto scene_pass_done = [&] {
    if (needs_projective_passes(scene)) {
      memory.forget(kProjectiveTextureAddress, kProjectiveTextureAddress + kProjectiveTextureBytes);
    }
  };
  read_pending();
  auto start = Clock::now();
  render_scene(scene, frame);  // 4
  scene_pass_done();
  // The renderer draws step 4 while the program sets up step 5's passes (shadow_pass.cpp).
  if (!result.jobs.empty()) glideShimFlush();
  finish_step(3, start);
  start = Clock::now();
  const BindShadowTexture bind = [&](const ShadowJob &job) {
    std::optional<FxU32> address = bind_shadow_texture(job, memory, frame);
    if (!address) {
      result.errors.push_back("'" + scene.objects[job.caster].name + "' casts no shadow from light " +
                              std::to_string(job.light) + ": step 1 cannot draw its texture again: " +
                              glideShimGetLastErrorMessage());
    }
    return address;
  };
  // 5, a light at a time (jobs are in light order). Between lights the depth buffer gets step
  // 4's surfaces back (a depth-only scene pass), so each light's marks start from them.
  std::vector<const ShadowJob *> same_light;
  for (std::size_t j = 0; j < result.jobs.size(); ++j) {
    same_light.push_back(&result.jobs[j]);
    if (j + 1 < result.jobs.size() && result.jobs[j + 1].light == result.jobs[j].light) continue;
    render_light_shadow_passes(same_light, options, bind);
    same_light.clear();
    if (j + 1 < result.jobs.size()) {
      grColorMask(FXFALSE, FXFALSE);
      render_scene(scene, frame);
      scene_pass_done();
      grColorMask(FXTRUE, FXFALSE);
    }
  }
  result.textures_loaded = memory.loads() > 0;
  finish_step(4, start);
  result.times.total_ms = elapsed_ms(frame_start);
  result.geometry = std::move(frame);
  // Errors are warnings too, so that a caller showing only warnings still shows them.
  result.warnings.insert(result.warnings.begin(), result.errors.begin(), result.errors.end());
  return result;
}

}  // namespace gs
