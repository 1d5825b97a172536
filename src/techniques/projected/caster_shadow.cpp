// Steps 1 to 3 of the projected shadow for one caster under one light (projected_frame.h): the
// light's view fitted to the caster; the receivers it reaches through, each given a texture of
// its own; each texture's cover (step 1), its receivers' (s, t) (step 3), its drawing (step 1)
// and read-back (step 2); then the whole shadow's texels checked against the screen
// (screen_check.h), and the shadow kept, refused, or tried again at a larger size. Spaces: world
// for the scene and the receivers' planes, light view and light clip for the textures (step 1),
// Glide screen (pixels, y down) for the light's size x size view and the camera.
#include "techniques/projected/projected_frame.h"
#include "techniques/step_clock.h"

#include "techniques/projected/caster_surface_from_light.h"
#include "techniques/projected/contact_strips.h"
#include "techniques/projected/hidden_layers.h"
#include "techniques/projected/pierced_receivers.h"
#include "techniques/projected/receiver_layers.h"
#include "techniques/projected/screen_check.h"

#include <glide_shim.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gs {
namespace {

using Clock = std::chrono::steady_clock;

// One try at the caster's shadow, at the size `fitted` was fitted at: its textures go to
// frame.caster_jobs.
struct CasterTry {
  ProjectedFrame &frame;
  std::size_t light;
  std::size_t caster;
  const LightView &fitted;
  // The caster's plane (world, positive on the light's side) when it is flat (planar_caster).
  const std::optional<glm::vec4> &caster_plane;
  float caster_back;  // the caster's farthest vertex from the light, light view depth (metres)
  // Step 1's cover of each texture's view (in split_into_textures' order) as fitted, the same
  // for the caster's texture for the other receivers and for each non-planar receiver it reaches
  // through (the mask changes only W and adds the cut to the silhouette), so it is made once per
  // caster.
  std::vector<std::optional<std::pair<LightView, CasterDraw>>> shared_covers;
  CasterSurfacesFromLight surfaces;  // step 3's, shared the same way
  // The pierced receiver's triangles in front of a caster part with a farther layer behind
  // (ReceiverLayers::over_buried), band -1's, while its textures are made.
  const std::vector<std::uint8_t> *over_buried = nullptr;
};

// What a texture is for: the receivers marked in `receivers`, each kept to its depth band
// (compute_receiver_coords); for a `pierced` one, the caster clipped to the light's side of its
// plane or masked by its surface, its farthest with `farthest` (SurfaceMask::farthest).
struct TextureFor {
  const std::vector<bool> &receivers;
  const std::vector<signed char> &bands;
  const PiercedReceiver *pierced;
  bool farthest;
};

// A pass of a texture split by layer: the pierced receiver's depth band in it, the triangles
// step 3 sorts by (its `hidden`: hidden_layers' classes, or band -4's marks), and the
// receiver's triangles whose own surface masks the texture (SurfaceMask::triangles; none: the
// receiver's whole surface, its farthest when the TextureFor says so).
struct LayerPass {
  const std::vector<signed char> *bands;
  const std::vector<std::uint8_t> *sorted_by = nullptr;
  const std::vector<std::uint8_t> *mask_triangles = nullptr;
  // Band -1's triangles in front of a hidden caster part (compute_receiver_coords' over_buried).
  const std::vector<std::uint8_t> *over_buried = nullptr;
};

// One texture of the caster for `part` (the `index`th of split_into_textures): step 1's cover,
// step 3, then, when a receiver shows it, step 1's drawing and step 2, for the pass `layer`.
// Returns whether band -1 left a triangle to band -2 (ReceiverCoords::hidden_left).
bool cast_texture(CasterTry &attempt, const TextureFor &what, const LightView &part,
                  std::size_t index, FxU32 bytes, const LayerPass &layer) {
  const std::vector<std::uint8_t> *mask_triangles = layer.mask_triangles;
  ProjectedFrame &frame = attempt.frame;
  const Scene &scene = frame.scene;
  const std::size_t caster = attempt.caster;
  const PiercedReceiver *pierced = what.pierced;
  ShadowJob job;
  job.caster = caster;
  job.light = attempt.light;
  job.view = part;
  SurfaceMask mask;
  if (pierced && pierced->planar) {
    // A world plane as a light-view plane: the inverse transpose of the view matrix.
    const glm::vec4 plane = glm::transpose(glm::inverse(part.view)) * pierced->plane;
    job.view.caster_planes.push_back(plane);
    job.view.edge_planes.push_back(plane);
  } else if (pierced) {
    mask = {&frame.geometry.objects[pierced->receiver], &pierced->caster_crossing,
            what.farthest && !mask_triangles, mask_triangles};
  }
  const SurfaceMask *masked = mask.receiver ? &mask : nullptr;
  auto step_start = Clock::now();
  CasterDraw draw;  // 1
  if (pierced && pierced->planar) {
    draw = cover_caster_from_light(scene, caster, job.view, frame.options);
  } else {
    std::optional<std::pair<LightView, CasterDraw>> &shared = attempt.shared_covers[index];
    if (!shared) {
      shared.emplace(part, CasterDraw{});
      shared->second = cover_caster_from_light(scene, caster, shared->first, frame.options);
    }
    job.view = shared->first;
    draw = shared->second;
    if (masked) mask_caster_cover(scene, caster, job.view, *masked, draw);
    if (masked) {
      job.view.contact_strips =
          contact_strips(job.view, pierced->contacts, scene.objects[caster], draw.closed,
                         frame.geometry.objects[pierced->receiver], scene.camera.position,
                         frame.geometry.view_projection);
    }
  }
  frame.finish_step(0, step_start);
  // Step 3 needs only step 1's cover, not its pixels: a texture whose receivers give step
  // 5 nothing to draw and the footprint check nothing to measure changes no byte of the
  // frame, so it is neither drawn nor read back (the other fighter, in front of a
  // fighter's shadow, receives nothing from it in most frames of the demo).
  step_start = Clock::now();
  job.receivers = compute_receiver_coords(
      scene, frame.geometry, caster, scene.lights[attempt.light], job.view, frame.options,
      &what.receivers, layer.bands, attempt.caster_back, &attempt.surfaces, layer.sorted_by,
      layer.over_buried, &attempt.caster_plane);  // 3
  frame.finish_step(2, step_start);
  const bool hidden_left = job.receivers.hidden_left;
  if (job.receivers.clipped.empty() && job.receivers.footprints.empty() &&
      std::none_of(job.receivers.triangles.begin(), job.receivers.triangles.end(),
                   [](const ShadowTriangle &t) { return t.reaches_caster; })) {
    frame.add_note(job.view);
    return hidden_left;
  }
  // A texture left unplaced is drawn on the direct path only when step 5 loads it.
  const std::size_t id = frame.texture_ids++;
  const std::optional<FxU32> placed = frame.result.textures.place(id, bytes);
  const bool drawn_now = placed || !job.view.direct_path;
  if (drawn_now) frame.read_pending();
  step_start = Clock::now();
  if (job.view.direct_path) grGlideGetState(&job.step1_state);
  if (drawn_now) {
    draw_caster_from_light(scene, job.view, placed.value_or(0), masked, draw);  // 1
    if (!job.view.direct_path) glideShimFlush();
  }
  frame.finish_step(0, step_start);
  if (!job.view.usable) {
    if (placed) frame.result.textures.release_from(*placed);
    frame.result.errors.push_back(job.view.problem);
    return hidden_left;
  }
  frame.add_note(job.view);
  if (job.view.direct_path) {
    step_start = Clock::now();
    job.texture = placed ? make_shadow_texture(job.view, frame.options, *placed)  // 2
                         : read_shadow_texture(job.view, frame.options);
    frame.finish_step(1, step_start);
  } else {
    frame.pending = ProjectedFrame::PendingRead{id, placed};  // 2, read_pending
  }
  job.texture.id = id;
  job.mask_farthest = masked && what.farthest && !mask_triangles;
  if (job.view.direct_path) {
    job.draw = std::move(draw);
    if (masked) job.mask_receiver = pierced->receiver;
    if (masked && mask_triangles) job.mask_triangles = *mask_triangles;
  }
  frame.caster_jobs.push_back(std::move(job));
  return hidden_left;
}

// The caster's textures for `what`: one per texture of its view (a map above 256 is several),
// more where a pass splits by layer. Returns whether a texture's band -1 left a triangle
// to band -2; stops at a texture TMU memory cannot hold, which it names in the frame's errors.
bool cast_textures(CasterTry &attempt, const TextureFor &what) {
  ProjectedFrame &frame = attempt.frame;
  const PiercedReceiver *pierced = what.pierced;
  bool hidden_left = false;
  const std::vector<LightView> parts = split_into_textures(attempt.fitted);
  attempt.shared_covers.resize(parts.size());
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
    if (what.farthest) {
      classes = hidden_layers(frame.geometry.objects[pierced->receiver], part, attempt.surfaces);
    }
    std::vector<signed char> layer_bands;
    if (!classes.empty()) layer_bands = what.bands, layer_bands[pierced->receiver] = -3;
    // Band -1's triangles in front of a hidden caster part (crossed by the caster, or
    // over_buried) that the receiver's own surface hides in part go to band -4, layer by layer
    // (hidden_layers.h, hidden_marked): band -1's texture would drop the caster's part between
    // the nearer surface and them (sunk-extra-lights_18418). Band -1 leaves them as hidden (its
    // marks without them), bands -2 and -3 skip them as marked. Only for a receiver that casts
    // nothing: one that casts shadows the parts its surface hides itself, which the error
    // measure leaves out, and band -1's texture is exact where the light reaches.
    const std::vector<std::uint8_t> *all_marks = attempt.over_buried;
    MarkedPasses marked;
    if (pierced && !pierced->planar && !what.farthest && all_marks &&
        !frame.scene.objects[pierced->receiver].casts_shadow) {
      marked = marked_passes(frame.geometry.objects[pierced->receiver], part, attempt.surfaces,
                             *all_marks);
      if (marked.layers > 0) layer_bands = what.bands, layer_bands[pierced->receiver] = -4;
    }
    const int passes = !classes.empty() ? 2 : 1 + marked.layers;
    for (int pass = 0; pass < passes; ++pass) {
      if (!frame.result.textures.can_hold(bytes)) {
        frame.result.errors.push_back(
            "TMU memory is too small: '" + frame.scene.objects[attempt.caster].name +
            "' casts no shadow from light " + std::to_string(attempt.light) + ", its " +
            std::to_string(part.size) + "x" + std::to_string(part.size) + " texture needs " +
            std::to_string(bytes) + " bytes");
        return hidden_left;
      }
      LayerPass layer{&what.bands, nullptr, nullptr, all_marks};
      if (!classes.empty()) {
        layer = {pass == 1 ? &layer_bands : &what.bands, &classes, pass == 1 ? &classes : nullptr,
                 all_marks};
      } else if (marked.layers > 0 && pass == 0) {
        layer.over_buried = &marked.band_one_marks;
      } else if (marked.layers > 0) {
        marked.layer_pass(pass);
        layer = {&layer_bands, &marked.taken, &marked.masking, all_marks};
      }
      if (cast_texture(attempt, what, part, index, bytes, layer)) hidden_left = true;
    }
  }
  return hidden_left;
}

// Every texture of the caster: one for the receivers it does not reach through, and for each it
// does, one clipped to the light's side of its plane or masked by its surface (two or three for a
// receiver whose own surface hides part of it from the light).
void cast_caster_textures(CasterTry &attempt, const ReachedReceivers &reached) {
  const Scene &scene = attempt.frame.scene;
  std::vector<bool> receivers(scene.objects.size(), true);
  // A receiver masking the caster takes the masked texture only nearer the light than the
  // caster's farthest vertex (light view depth), and the whole caster's beyond it: there
  // every caster point on the light's ray is in front of it, buried or hidden or not, and
  // shadows it (a foot in a dune shadows the dune's far slope).
  std::vector<signed char> bands(scene.objects.size(), 0);
  for (const PiercedReceiver &p : reached.pierced) {
    receivers[p.receiver] = !p.planar;
    if (!p.planar) bands[p.receiver] = 1;
  }
  for (std::size_t r : reached.refused) receivers[r] = false;
  bool others = false;  // a receiver left for the whole caster's texture
  for (std::size_t r = 0; r < scene.objects.size(); ++r) {
    others = others || (receivers[r] && r != attempt.caster && scene.objects[r].receives_shadow);
  }
  if (others) cast_textures(attempt, {receivers, bands, nullptr, false});
  for (const PiercedReceiver &p : reached.pierced) {
    std::vector<bool> only(scene.objects.size(), false);
    only[p.receiver] = true;
    std::vector<signed char> near(scene.objects.size(), 0);
    if (!p.planar) near[p.receiver] = -1;
    // Band -1's triangles among those the receiver's surface hides in part: the ones the
    // caster passes through, or in front of a caster part with a farther layer behind.
    std::vector<std::uint8_t> front_marks = p.receiver_crossing;
    for (const auto &[r, marks] : reached.layers.over_buried) {
      if (r != p.receiver) continue;
      front_marks.resize(marks.size(), 0);
      for (std::size_t k = 0; k < marks.size(); ++k) front_marks[k] |= marks[k];
    }
    attempt.over_buried = front_marks.empty() ? nullptr : &front_marks;
    // Nothing of the caster on the light's side of the receiver's nearest surface: no
    // shadow on that surface.
    const bool hidden_left = p.casts && cast_textures(attempt, {only, near, &p, false});
    // The receiver's parts its own surface hides from the light, masked by its farthest
    // light-facing surface (step 3's band -2), when band -1 left some; with a middle layer
    // that may be shadowed, that layer masked by the hidden parts' nearest surface (-3).
    if (!p.planar && (hidden_left || !p.casts)) {
      near[p.receiver] = -2;
      cast_textures(attempt, {only, near, &p, true});
    }
  }
  attempt.over_buried = nullptr;
}

}  // namespace

void cast_caster_shadow(ProjectedFrame &frame, std::size_t light, std::size_t caster) {
  const Scene &scene = frame.scene;
  // The size the caster's shadow is tried at: the options', then (grow_to_accepted) the
  // smallest larger one the estimates accept after a refusal as too coarse, which is then
  // checked again the same way. A refused attempt leaves nothing behind in the frame.
  ProjectedShadowOptions sized = frame.options;
  std::string grown_from;  // the first attempt's refusal's reason, for the note
  for (;;) {
    const std::size_t errors_before = frame.result.errors.size();
    const std::size_t warnings_before = frame.result.warnings.size();
    const float footprint_before = frame.result.texel_footprint_px;
    const EdgeErrorEstimate of_all_before = frame.edge_error_of_all;
    const auto start = Clock::now();
    const LightView fitted = fit_light_view(scene, caster, light, sized);  // 1
    frame.result.times.ms[0] += elapsed_ms(start);
    if (!fitted.usable) {
      if (!fitted.outside_beam) frame.result.errors.push_back(fitted.problem);
      return;
    }
    // This caster's textures (a map above 256 is several, and one more per receiver it reaches
    // through); kept only if every one's texels are fine enough for the screen where the shadow
    // falls.
    frame.caster_jobs.clear();
    const FxU32 caster_mark = frame.result.textures.mark();
    // Whether the caster is flat for this light (planar_caster), found once here: every texture's
    // steps 1 and 3 ask.
    const std::optional<glm::vec4> caster_plane =
        planar_caster(scene.objects[caster], scene.lights[light].position);
    CasterTry attempt{frame, light, caster, fitted, caster_plane,
                      farthest_depth(scene.objects[caster], fitted.view), {},
                      CasterSurfacesFromLight(scene.objects[caster]), nullptr};
    const auto reach_start = Clock::now();
    const ReachedReceivers reached =
        reached_receivers(scene, frame.geometry, light, caster, fitted, caster_plane,
                          frame.result.errors);
    frame.result.times.ms[0] += elapsed_ms(reach_start);
    cast_caster_textures(attempt, reached);  // 1, 3 and 2
    const ScreenCheck check = check_against_screen(frame, light, caster, fitted.size);
    if (check.reason) {
      frame.result.textures.release_from(caster_mark);  // its textures are not used
      if (frame.options.grow_to_accepted && check.accepted.size > fitted.size) {
        frame.result.errors.resize(errors_before);
        frame.result.warnings.resize(warnings_before);
        frame.result.texel_footprint_px = footprint_before;
        frame.edge_error_of_all = of_all_before;
        if (grown_from.empty()) grown_from = *check.reason;
        sized.size = check.accepted.size, sized.auto_size = false;
        continue;
      }
      frame.result.errors.push_back(*check.reason + "; " + kCastsNoShadow);
      return;
    }
    if (!grown_from.empty()) {
      frame.result.warnings.push_back(grown_shadow_note(grown_from, fitted.size));
    }
    frame.result.sizes.push_back({light, caster, fitted.size});
    frame.edge_error_taken += check.edge_error_pixels;
    for (ShadowJob &job : frame.caster_jobs) frame.result.jobs.push_back(std::move(job));
    frame.caster_jobs.clear();  // what is left of them is not a texture to read (read_pending)
    return;
  }
}

}  // namespace gs
