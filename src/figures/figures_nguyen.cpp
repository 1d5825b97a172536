// Nguyen 1999's figures 1 and 4-9, drawn by the projected shadow texture's own steps
// (projected_shadow.h) on the Glide shim: the fight, the five steps one by one. Spaces: world;
// the light's 256 x 256 view (pixels = texels of the shadow texture, y down); the camera's
// screen (pixels, y down); Glide texture units (0..256).
#include "figures/figures_kit.h"
#include "figures/nguyen_steps.h"

#include "scene/fight_scene.h"
#include "scene/fighter.h"
#include "measure/ground_truth.h"
#include "measure/metrics.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide_shim.h>
#include <glideutl.h>

#include <algorithm>

namespace gs {
namespace {

using figures::alpha_picture;
using figures::alpha_set;
using figures::against_truth;
using figures::check;
using figures::count;
using figures::count_both;
using figures::format;
using figures::from_the_light;
using figures::kFighter;
using figures::kFloor;
using figures::kListing4Gamma;
using figures::kStep;
using figures::Mask;
using figures::near_border;
using figures::run_steps;
using figures::Steps;
using figures::Words;

}  // namespace

namespace {

// The box (screen pixels) around the set pixels of `mask`, `pad` wider on each side and kept
// inside the frame; the whole frame when the mask is empty.
struct Box {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // inclusive
};
Box bounds(const Mask &mask, int width, int height, int pad) {
  Box box{width, height, -1, -1};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (!mask[static_cast<std::size_t>(y * width + x)]) continue;
      box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x), std::max(box.y1, y)};
    }
  }
  if (box.x1 < 0) return {0, 0, width - 1, height - 1};
  return {std::max(box.x0 - pad, 0), std::max(box.y0 - pad, 0), std::min(box.x1 + pad, width - 1),
          std::min(box.y1 + pad, height - 1)};
}

Words cropped(const Words &words, const Box &box) {
  Words out;
  out.width = box.x1 - box.x0 + 1;
  out.height = box.y1 - box.y0 + 1;
  for (int y = box.y0; y <= box.y1; ++y) {
    for (int x = box.x0; x <= box.x1; ++x) out.data.push_back(words.at(x, y));
  }
  return out;
}

void outline(FigureImage &image, const Box &box) {  // yellow, one pixel outside the box
  auto plot = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    const std::size_t i = static_cast<std::size_t>(y * image.width + x) * 3;
    image.rgb[i] = 255, image.rgb[i + 1] = 230, image.rgb[i + 2] = 0;
  };
  for (int x = box.x0 - 1; x <= box.x1 + 1; ++x) plot(x, box.y0 - 1), plot(x, box.y1 + 1);
  for (int y = box.y0 - 1; y <= box.y1 + 1; ++y) plot(box.x0 - 1, y), plot(box.x1 + 1, y);
}

}  // namespace

void figure_nguyen_1(Figure &figure, FigureFault fault) {
  // The blue fighter's front kick landing: the light low behind him, the camera close on the
  // red fighter's lit side, as the demo shows it.
  constexpr float kTime = 5.6f;
  FightScene fight(kFigureWindowWidth, kFigureWindowHeight, 256);
  Scene scene = fight.at(kTime);
  // The article's pipeline draws a simplified caster into the texture; the fight itself casts
  // from the fighters' own meshes, so the figure gives them the simplified one back.
  for (int i = 0; i < 2; ++i)
    scene.objects[FightScene::kFighters[i]].shadow_mesh = build_fighter_lod(fight_loop_pose(i, kTime));
  const std::size_t receiver = FightScene::kFighters[fight_light_side(kTime) < 0.5f ? 1 : 0];
  const std::size_t caster = receiver == FightScene::kFighters[0] ? FightScene::kFighters[1] : FightScene::kFighters[0];
  Words mask;
  const Words frame = figures::render_frame(figures::shadowed_by("projected", fault), {}, scene, &mask);
  const Mask on_receiver = figures::coverage(scene, receiver);
  Mask shadow_on_receiver = figures::non_zero(mask);
  for (std::size_t i = 0; i < shadow_on_receiver.size(); ++i) shadow_on_receiver[i] &= on_receiver[i];
  // The truth: the ray-cast shadow of the mesh the technique draws for the caster (its
  // simplified shadow mesh) on the receiver's own mesh.
  scene.objects[caster].mesh = caster_mesh(scene.objects[caster]);
  GroundTruth truth;
  std::string error;
  const bool traced = compute_ground_truth(scene, truth, error);
  Mask true_shadow(shadow_on_receiver.size(), 0), true_ring(shadow_on_receiver.size(), 0);
  for (std::size_t i = 0; traced && i < true_shadow.size(); ++i) {
    true_shadow[i] = truth.shadow[i] && truth.object[i] == static_cast<int>(receiver);
    true_ring[i] = truth.shadow[i] && truth.object[i] == static_cast<int>(FightScene::kRing);
  }
  const long ours = count(shadow_on_receiver), truths = count(true_shadow);
  const long both = count_both(shadow_on_receiver, true_shadow);
  const long ring = count_both(figures::non_zero(mask), true_ring), ring_truth = count(true_ring);
  // The inset: the receiver's shadowed part (technique or truth), magnified twice, and the
  // same box as a map of the comparison.
  Mask either = shadow_on_receiver;
  for (std::size_t i = 0; i < either.size(); ++i) either[i] |= true_shadow[i];
  const Box box = bounds(either, frame.width, frame.height, 4);
  FigureImage whole = figures::to_image(frame, kListing4Gamma);
  const FigureImage inset = figures::magnified(figures::to_image(cropped(frame, box), kListing4Gamma), 2);
  Words comparison = cropped(frame, box);
  for (int y = box.y0; y <= box.y1; ++y) {
    for (int x = box.x0; x <= box.x1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * frame.width + x);
      const FxU16 grey = 0x4208, white = 0xFFFF, red = 0xF800, cyan = 0x07FF;
      const FxU16 word = shadow_on_receiver[i] && true_shadow[i] ? white : shadow_on_receiver[i] ? red
                         : true_shadow[i] ? cyan : on_receiver[i] ? grey : 0;
      comparison.data[static_cast<std::size_t>((y - box.y0) * comparison.width + x - box.x0)] = word;
    }
  }
  outline(whole, box);
  const char *receiver_name = receiver == FightScene::kFighters[0] ? "red" : "blue";
  figure.image = figures::compose({{whole, "THE FIGHT AT 5.6 S"},
                                   {inset, "THE BOX X2"},
                                   {figures::magnified(figures::to_image(comparison, 1.0f), 2), "AGAINST THE TRUTH"}});
  figure.shows = format("The demo's fight at 5.6 s, 320x256, projected shadow textures of 256x256 "
                        "under the low spotlight behind the attacker: his shadow runs across the "
                        "ring's mat and climbs the %s fighter's body. Centre: the yellow box "
                        "magnified twice. Right: the same box, the %s fighter grey, white where "
                        "both the technique and the ray-cast truth shadow him, red where only the "
                        "technique does, cyan where only the truth does.",
                        receiver_name, receiver_name);
  figure.checks.push_back(check(
      "one fighter's shadow is cast onto the other (inter-object shadow) where the ray-cast truth puts it: "
      "area within 10% of the truth's, overlap over union >= 90%",
      traced && truths >= 500 && std::abs(ours - truths) * 10 <= truths && both * 10 >= (ours + truths - both) * 9,
      traced ? format("%ld shadowed pixels on the fighter, truth %ld, overlap %ld", ours, truths, both) : error));
  figure.checks.push_back(check(
      "the shadows also fall on the ring: >= 90% of the ray-cast shadow on the ring is shadowed",
      traced && ring_truth >= 500 && ring * 10 >= ring_truth * 9,
      format("%ld of the truth's %ld shadowed ring pixels", ring, ring_truth)));
}

void figure_nguyen_4(Figure &figure, FigureFault fault) {
  Scene scene = figures::article_scene();
  const Words unshadowed = figures::render_frame("none", {}, scene);
  if (fault == FigureFault::FullStrength) scene.lights[0].shadow_strength = 1.0f;
  ProjectedShadowOptions options;
  const Steps steps = run_steps(scene, options, glm::mat4(1.0f), fault);
  const Words frame = figures::read_back(scene.width, scene.height);
  render_shadow_mask(options, steps.frame);
  const Words mask = figures::read_back(scene.width, scene.height);
  // Inside the shadow (a pixel whose four neighbours are shadowed too: past bilinear's edge),
  // what is left of the lit colour: 1 - 170/255 of it, a third.
  std::vector<double> left;
  for (int y = 1; y + 1 < scene.height; ++y) {
    for (int x = 1; x + 1 < scene.width; ++x) {
      if (!mask.at(x, y) || !mask.at(x - 1, y) || !mask.at(x + 1, y) || !mask.at(x, y - 1) ||
          !mask.at(x, y + 1)) {
        continue;
      }
      if (((unshadowed.at(x, y) >> 5) & 0x3F) < 16) continue;  // too dark to measure a ratio
      left.push_back(1.0 - figures::darkening(unshadowed.at(x, y), frame.at(x, y)));
    }
  }
  std::sort(left.begin(), left.end());
  const double median = left.empty() ? 0.0 : left[left.size() / 2];
  // The step's part of the ray-cast shadow, and how much of it the technique shadowed.
  Mask truth, counted;
  const bool traced = figures::true_shadow(scene, truth, counted);
  const Mask step = figures::coverage(scene, kStep);
  for (std::size_t i = 0; traced && i < truth.size(); ++i) truth[i] = truth[i] && counted[i] && step[i];
  const long on_step = traced ? count_both(figures::non_zero(mask), truth) : 0, step_truth = traced ? count(truth) : 0;
  figure.image = figures::compose({{figures::to_image(frame, kListing4Gamma), "THE FINAL SHADOW"}});
  figure.shows = "Our scene: a fighter in guard on a floor with a step, the spotlight in front, "
                 "above and to his right; his shadow from a 256x256 ARGB_4444 texture, bilinear, "
                 "at iterated alpha 170 (Listings 3-5), across the floor and up the step.";
  figure.checks.push_back(check("the caster's shadow is drawn", steps.usable && left.size() >= 500,
                                format("%zu pixels inside the shadow", left.size())));
  figure.checks.push_back(check("iterated alpha 170 leaves 1 - 170/255 = 0.33 of the lit colour inside the shadow",
                                median > 0.28 && median < 0.39,
                                format("median remaining fraction %.3f (green field)", median)));
  figure.checks.push_back(check("the shadow is cast on a non-planar receiver: it climbs the step (>= 90% of the ray-cast shadow on the step)",
                                step_truth >= 100 && on_step * 10 >= step_truth * 9,
                                format("%ld of the truth's %ld shadowed step pixels", on_step, step_truth)));
}

void figure_nguyen_5(Figure &figure, FigureFault fault) {
  const Scene scene = figures::article_scene();
  Scene light = from_the_light(scene);
  if (fault == FigureFault::EyeBesideLight) light.camera.position += glm::vec3(0.3f, 0.0f, 0.0f);
  Words camera_mask, light_mask;
  figures::render_frame("projected", {}, scene, &camera_mask);
  const Words frame = figures::render_frame("projected", {}, light, &light_mask);
  const long caster = count(figures::coverage(light, kFighter));
  const long seen_from_camera = count(figures::non_zero(camera_mask));
  const long seen_from_light = count(figures::non_zero(light_mask));
  figure.image = figures::compose({{figures::to_image(frame, kListing4Gamma), "FROM THE LIGHT"},
                                   {figures::to_image(light_mask, 1.0f), "SHADOW SEEN FROM THE LIGHT"}});
  figure.shows = "The same frame, shadows and all, rendered with the camera at the light (the "
                 "view step 1 uses, 256x256), and the technique's shadow mask from there: only "
                 "a thin rim around the figure, where bilinear filtering reaches past the silhouette.";
  figure.checks.push_back(check(
      "from the light, the figure hides exactly the shadow it casts (visible shadow under 2% of the figure's pixels)",
      caster > 1000 && seen_from_light * 50 < caster && seen_from_camera >= 500,
      format("%ld shadowed pixels visible from the light against %ld figure pixels; %ld from the camera",
             seen_from_light, caster, seen_from_camera)));
}

namespace {

constexpr FxU16 kUnflaggedGrey = 0x4208;  // 565 of (64, 64, 64)

// The receivers' triangles drawn from the light's view (step 1's camera), W-buffered: those
// Listing 2 flags (facing the light, not wholly outside its view) each in its own flat colour,
// those facing away in grey; triangles wholly outside the view are not drawn.
Words flagged_triangles(const Scene &scene, FigureFault fault) {
  const LightView view = fit_light_view(scene, kFighter, 0, {});
  const glm::mat4 light_clip = view.projection * view.view;
  const glm::vec3 light = scene.lights[0].position;
  set_scene_state();
  grCullMode(GR_CULL_DISABLE);
  grClipWindow(0, 0, static_cast<FxU32>(view.size), static_cast<FxU32>(view.size));
  grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST);
  std::uint32_t hash = 2166136261u;
  for (std::size_t r = 0; r < scene.objects.size(); ++r) {
    if (r == kFighter) continue;
    const SceneObject &object = scene.objects[r];
    for (const glm::uvec3 &t : object.mesh.triangles) {
      glm::vec3 world[3];
      glm::vec4 clip[3];
      unsigned outside = ~0u;
      const unsigned index[3] = {t.x, t.y, t.z};
      for (int k = 0; k < 3; ++k) {
        world[k] = glm::vec3(object.model_to_world * glm::vec4(object.mesh.positions[index[k]], 1.0f));
        clip[k] = light_clip * glm::vec4(world[k], 1.0f);
        const glm::vec4 &p = clip[k];
        outside &= (p.x < -p.w) | (p.x > p.w) << 1 | (p.y < -p.w) << 2 | (p.y > p.w) << 3 | (p.w <= 0.0f) << 4;
      }
      if (outside != 0) continue;
      const bool facing = (glm::dot(glm::cross(world[1] - world[0], world[2] - world[0]), light - world[0]) > 0.0f) !=
                          (fault == FigureFault::FacingInverted);
      hash = (hash ^ 0x9E3779B9u) * 16777619u;
      GrVertex v[3];
      for (int k = 0; k < 3; ++k) {
        v[k] = to_screen(clip[k], view.size, view.size);
        v[k].r = facing ? static_cast<float>(96 + (hash % 160)) : 64.0f;
        v[k].g = facing ? static_cast<float>(96 + ((hash >> 8) % 160)) : 64.0f;
        v[k].b = facing ? static_cast<float>(96 + ((hash >> 16) % 160)) : 64.0f;
      }
      guDrawTriangleWithClip(&v[0], &v[1], &v[2]);
    }
  }
  const Words words = figures::read_back(view.size, view.size);
  grClipWindow(0, 0, static_cast<FxU32>(scene.width), static_cast<FxU32>(scene.height));
  set_scene_state();
  return words;
}

}  // namespace

void figure_nguyen_6(Figure &figure, FigureFault fault) {
  const Scene scene = figures::article_scene();
  Scene receivers = from_the_light(scene);
  receivers.objects[kFighter].mesh = Mesh{};  // drawn without the caster (its shadow mesh stays)
  // The reference: the surfaces the light sees, ray cast from the light without the caster.
  Scene light_without_caster = receivers;
  light_without_caster.objects.pop_back();
  GroundTruth truth;
  std::string error;
  const bool traced = compute_ground_truth(light_without_caster, truth, error);
  if (fault == FigureFault::EyeBesideLight) receivers.camera.position += glm::vec3(0.3f, 0.0f, 0.0f);
  render_scene(receivers, project_scene(receivers));
  const Words frame = figures::read_back(receivers.width, receivers.height);
  Mask receiver_pixels = figures::coverage(receivers, kFloor);
  const Mask step = figures::coverage(receivers, kStep);
  long same_surface = 0;
  for (std::size_t i = 0; i < receiver_pixels.size(); ++i) {
    const int drawn = step[i] ? static_cast<int>(kStep) : receiver_pixels[i] ? static_cast<int>(kFloor) : -1;
    same_surface += traced && drawn == truth.object[i];
    receiver_pixels[i] |= step[i];
  }
  const Words flagged = flagged_triangles(scene, fault);
  long on_flagged = 0;
  for (std::size_t i = 0; i < receiver_pixels.size(); ++i) {
    on_flagged += receiver_pixels[i] && flagged.data[i] != 0 && flagged.data[i] != kUnflaggedGrey;
  }
  const long seen = count(receiver_pixels);
  figure.image = figures::compose({{figures::to_image(frame, kListing4Gamma), "RECEIVERS FROM THE LIGHT"},
                                   {figures::to_image(flagged, 1.0f), "TRIANGLES LISTING 2 FLAGS"}});
  figure.shows = "Left: the floor and the step (the receivers) rendered from the light's view "
                 "without the caster: the light-space x, y that step 3 turns into (s, t). Right: "
                 "their triangles in that view, each triangle Listing 2 flags (facing the light, "
                 "not wholly outside its view) in its own flat colour, those facing away in grey.";
  const long pixels = static_cast<long>(receiver_pixels.size());
  figure.checks.push_back(check(
      "the left panel is the receivers as the light sees them: each pixel shows the surface (floor, step, none) a ray cast from the light meets first (>= 99% of pixels)",
      traced && same_surface * 100 >= pixels * 99,
      traced ? format("%ld of %ld pixels", same_surface, pixels) : error));
  figure.checks.push_back(check(
      "every receiver pixel the light sees lies on a triangle Listing 2 flags",
      seen > 10000 && on_flagged == seen,
      format("%ld of %ld receiver pixels on flagged triangles", on_flagged, seen)));
}

void figure_nguyen_7(Figure &figure, FigureFault fault) {
  const Scene scene = figures::article_scene();
  const glm::mat4 view = fault == FigureFault::NoCleanBorder ? figures::border_cutting_view() : glm::mat4(1.0f);
  const Steps steps = run_steps(scene, {}, view, fault);
  const Words &words = steps.light_words;
  long other = 0;
  for (FxU16 w : words.data) other += w != 0 && w != 0xF000;
  // The caster's silhouette from the light, ray cast (not rasterised) from the shadow mesh
  // step 1 drew.
  Scene light = from_the_light(scene);
  light.objects[kFighter].mesh = light.objects[kFighter].shadow_mesh;
  GroundTruth truth;
  std::string error;
  Mask silhouette(static_cast<std::size_t>(light.width * light.height), 0);
  if (compute_ground_truth(light, truth, error)) {
    for (std::size_t i = 0; i < silhouette.size(); ++i) silhouette[i] = truth.object[i] == static_cast<int>(kFighter);
  }
  const Mask texture = alpha_set(words);
  const long both = count_both(silhouette, texture);
  const long either = count(silhouette) + count(texture) - both;
  figure.image = figures::compose({{alpha_picture(words), "ALPHA OF THE 4444 TEXTURE"}});
  figure.shows = "Step 1's 256x256 frame-buffer words read back (step 2) and read as ARGB_4444: "
                 "white where alpha is 1111b, black where it is 0; nothing else occurs.";
  figure.checks.push_back(check("the texture holds only 0xF000 (alpha 1111b, colour 0) and 0 (background)",
                                other == 0 && !words.data.empty(),
                                format("%ld texels with another value", other)));
  figure.checks.push_back(check("its alpha is the caster's silhouette as a ray cast from the light finds it (overlap over union >= 99%)",
                                either > 1000 && both * 100 >= either * 99,
                                format("overlap %ld / union %ld texels", both, either)));
  figure.checks.push_back(check("the silhouette keeps a clean border of at least two texels",
                                near_border(texture, words.width, 2) == 0,
                                format("%ld silhouette texels within 2 of the edge",
                                       near_border(texture, words.width, 2))));
}

void figure_nguyen_8(Figure &figure, FigureFault fault) {
  const Scene scene = figures::article_scene();
  Scene light = from_the_light(scene);
  light.objects[kFighter].mesh = Mesh{};  // the receivers alone; the shadow mesh still casts
  ProjectedShadowOptions options;
  options.bilinear = false;  // texel for pixel
  const ShadowFrame frame = render_projected_shadows(light, options, false);
  const Words receivers = figures::read_back(light.width, light.height);
  render_shadow_mask(options, frame);
  // Step 5 from the light, read back now: run_steps below renders the camera's frame over it.
  Words step5 = figures::read_back(light.width, light.height);
  const Steps steps = run_steps(scene, options);
  if (fault == FigureFault::StaleReadBack) step5 = figures::read_back(light.width, light.height);
  const Mask texture = alpha_set(steps.light_words);
  // The superimposition: the receivers from the light with the texture's alpha in red over them.
  FigureImage picture = figures::to_image(receivers, kListing4Gamma);
  for (std::size_t i = 0; i < texture.size(); ++i) {
    if (!texture[i]) continue;
    picture.rgb[3 * i] = static_cast<std::uint8_t>((picture.rgb[3 * i] + 255) / 2);
    picture.rgb[3 * i + 1] = static_cast<std::uint8_t>(picture.rgb[3 * i + 1] / 2);
    picture.rgb[3 * i + 2] = static_cast<std::uint8_t>(picture.rgb[3 * i + 2] / 2);
  }
  // Checked on the words the right panel shows, so a panel read from the wrong frame fails.
  const Mask projected = figures::non_zero(step5);
  const long both = count_both(projected, texture);
  const long either = count(projected) + count(texture) - both;
  figure.image = figures::compose({{picture, "TEXTURE OVER THE RECEIVERS"},
                                   {figures::to_image(step5, 1.0f), "STEP 5 FROM THE LIGHT"}});
  figure.shows = "Left: the receivers from the light with the shadow texture's alpha laid over them "
                 "in red. Right: step 5's shadow mask drawn with the camera at the light (point "
                 "sampled): the (s, t) of step 3 put each texel on the pixel under it.";
  figure.checks.push_back(check(
      "(s, t) are the light-view x, y: in the right panel, from the light, the projected shadow covers exactly the texture's texels (overlap over union >= 99%)",
      either > 1000 && both * 100 >= either * 99,
      format("overlap %ld / union %ld pixels", both, either)));
}

void figure_nguyen_9(Figure &figure, FigureFault fault) {
  Scene scene = figures::article_scene();
  scene.lights[0].shadow_strength = 1.0f;  // the texture at full opacity: black where alpha is 1111b
  ProjectedShadowOptions options;
  const Steps steps = run_steps(scene, options, glm::mat4(1.0f), fault);
  const Words frame = figures::read_back(scene.width, scene.height);
  render_shadow_mask(options, steps.frame);
  const Words mask = figures::read_back(scene.width, scene.height);
  const MaskErrors errors = against_truth(scene, mask);
  figure.image = figures::compose({{figures::to_image(frame, kListing4Gamma), "SHADOW TEXTURE PROJECTED"},
                                   {figures::to_image(mask, 1.0f), "WHERE IT DARKENS"}});
  figure.shows = "The scene with the shadow texture projected at full strength (iterated alpha 255) "
                 "onto the triangles the light sees, and the pixels it darkened.";
  figure.checks.push_back(check(
      "the projected texture lands where the shadow truly is: under 1% of floor and step pixels differ from the ray-cast shadow of the mesh step 1 drew",
      errors.receiver_pixels > 10000 && errors.misclassified < 0.01,
      format("%.2f%% misclassified (%.2f%% within a pixel of the true edge) of %ld receiver pixels",
             100 * errors.misclassified, 100 * (errors.false_light_band + errors.false_shadow_band),
             errors.receiver_pixels)));
}

}  // namespace gs
