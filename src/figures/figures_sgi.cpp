// Segal et al. 1992's figures, drawn by the projective-texture light passes (slide_projector.h,
// spotlight.h) on the Glide shim and, for Figure 4, by the depth-map technique too. Spaces:
// world; the light's square view (pixels, y down), whose 256 pixels span the slide or beam map;
// the camera's screen.
#include "figures/figures_kit.h"

#include "measure/ground_truth.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/light_passes/slide_projector.h"
#include "scene/spotlight.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace gs {
namespace {

// The scene of scenes/slide_projector.json: a floor, a box and a pillar, a checker slide from
// above-left and a rings slide from the right, a dim ambient light.
Scene projector_scene() {
  Scene scene;
  scene.width = kFigureWindowWidth;
  scene.height = kFigureWindowHeight;
  scene.ambient = glm::vec3(0.2f);
  scene.camera.position = glm::vec3(0.0f, 4.0f, 7.0f);
  scene.camera.target = glm::vec3(0.0f, 0.6f, 0.0f);
  scene.camera.fov_degrees = 50.0f;
  SpotLight checker;
  checker.position = glm::vec3(-2.5f, 5.0f, 2.0f);
  checker.target = glm::vec3(0.0f);
  checker.cone_degrees = 50.0f;
  checker.slide = "checker";
  SpotLight rings;
  rings.position = glm::vec3(3.0f, 4.0f, 1.0f);
  rings.target = glm::vec3(0.5f, 0.0f, 0.0f);
  rings.cone_degrees = 40.0f;
  rings.color = glm::vec3(1.0f, 0.9f, 0.7f);
  rings.slide = "rings";
  scene.lights = {checker, rings};
  SceneObject floor;
  floor.name = "floor";
  floor.mesh = make_plane(8.0f, 16);
  floor.mesh.set_color(glm::vec3(0.9f));
  SceneObject box;
  box.name = "box";
  box.mesh = make_box(glm::vec3(0.5f));
  box.mesh.set_color(glm::vec3(0.9f, 0.5f, 0.3f));
  box.model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f));
  SceneObject pillar;
  pillar.name = "pillar";
  pillar.mesh = make_cylinder(0.3f, 1.6f, 24, true);
  pillar.mesh.set_color(glm::vec3(0.4f, 0.6f, 0.9f));
  pillar.model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 0.0f, -0.5f));
  scene.objects = {floor, box, pillar};
  return scene;
}

}  // namespace

void figure_sgi_3(Figure &figure, FigureFault fault) {
  Scene scene = projector_scene();
  const SpotLight projector = scene.lights[0];  // where the figure says it stands
  if (fault == FigureFault::LightMoved) scene.lights[0].position += glm::vec3(0.3f, 0.0f, 0.0f);
  render_scene(scene, project_scene(scene));
  const figures::Words frame = figures::read_back(scene.width, scene.height);
  figures::Words slide;
  int side = 0;
  slide.data = slide_texels(scene.lights[0], side);
  slide.width = slide.height = side;
  // The check: the scene seen from the checker projector itself, lit by it alone and by the
  // ambient light alone. Every surface it sees must be brightened exactly where the slide's
  // texel under that pixel is bright (its 256 pixels span the slide's side).
  Scene from_projector = figures::seen_from(scene, projector.position, projector.target,
                                            projector.cone_degrees, 256);
  from_projector.lights.resize(1);
  from_projector.background = glm::vec3(0.0f);
  render_scene(from_projector, project_scene(from_projector));
  const figures::Words lit = figures::read_back(256, 256);
  Scene ambient_only = from_projector;
  ambient_only.lights.clear();
  render_scene(ambient_only, project_scene(ambient_only));
  const figures::Words ambient = figures::read_back(256, 256);
  long surfaces = 0, agree = 0;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      if (ambient.at(x, y) == 0) continue;  // background
      // Away from the slide's edges, where bilinear filtering blends two texels: the texels
      // a texel either side are the same.
      const FxU16 texel = slide.at(x * side / 256, y * side / 256);
      const int reach = 256 / side;
      bool uniform = true;
      for (int dy = -reach; dy <= reach; dy += reach) {
        for (int dx = -reach; dx <= reach; dx += reach) {
          const int sx = std::clamp(x + dx, 0, 255) * side / 256, sy = std::clamp(y + dy, 0, 255) * side / 256;
          uniform = uniform && slide.at(sx, sy) == texel;
        }
      }
      if (!uniform) continue;
      ++surfaces;
      // The slide adds 1 to the ambient 0.2, six times the ambient level.
      const int before = (ambient.at(x, y) >> 5) & 0x3F, after = (lit.at(x, y) >> 5) & 0x3F;
      const bool brightened = 2 * after >= 5 * before;
      agree += brightened == (texel != 0);
    }
  }
  figure.image = figures::compose({{figures::magnified(figures::to_image(slide, 1.0f), 256 / std::max(side, 1)), "THE CHECKER SLIDE"},
                                   {figures::to_image(frame, figures::kListing4Gamma), "THE SCENE THROUGH TWO SLIDES"}});
  figure.shows = "Left: the 64x64 RGB 565 checker slide (its outer texel black, so clamp adds "
                 "nothing outside it). Right: the scene of scenes/slide_projector.json in the "
                 "paper's three passes (depth; ambient plus each slide where z is equal; times "
                 "the surface colour): a checker slide from the upper left and a rings slide "
                 "from the right.";
  figure.checks.push_back(figures::check(
      "the slide is projected onto the scene: seen from the projector, surfaces are brightened exactly where the slide is bright (>= 98% of pixels a texel away from the slide's edges)",
      surfaces > 10000 && agree * 100 >= surfaces * 98,
      figures::format("%ld of %ld surface pixels agree with the slide texel under them", agree, surfaces)));
}

namespace {

// The paper's Figure 4 scene (scenes/spotlight.json): Figure 3's floor, box and pillar, the box
// and pillar moved apart, under a spotlight whose beam map is a window gobo, its attenuation
// exact per pixel.
Scene spotlight_scene() {
  Scene scene = projector_scene();
  scene.ambient = glm::vec3(0.12f, 0.12f, 0.14f);
  SpotLight spot;
  spot.position = glm::vec3(-1.5f, 5.5f, 2.5f);
  spot.target = glm::vec3(0.2f, 0.0f, -0.3f);
  spot.cone_degrees = 55.0f;
  spot.color = glm::vec3(1.0f, 0.95f, 0.85f);
  spot.beam = "gobo";
  spot.attenuation = {AttenuationMode::PerPixel, 0.2f, 0.0f, 0.03f};
  scene.lights = {spot};
  scene.objects[0].casts_shadow = false;  // the floor
  scene.objects[1].model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(-0.6f, 0.5f, 0.2f));
  scene.objects[2].model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(1.3f, 0.0f, -0.6f));
  return scene;
}

// Depth codes as grey levels, nearer darker, stretched over the codes present (0xFFFF, the
// cleared far plane, white).
figures::Words depth_as_grey(const figures::Words &depth) {
  FxU16 nearest = 0xFFFF, farthest = 0;
  for (FxU16 code : depth.data) {
    if (code == 0xFFFF) continue;
    nearest = std::min(nearest, code);
    farthest = std::max(farthest, code);
  }
  figures::Words grey = depth;
  for (FxU16 &code : grey.data) {
    const int level = code == 0xFFFF || farthest <= nearest
                          ? 63
                          : 8 + 48 * (code - nearest) / (farthest - nearest);  // 6-bit green
    code = static_cast<FxU16>((level >> 1) << 11 | level << 5 | (level >> 1));
  }
  return grey;
}

}  // namespace

void figure_sgi_4(Figure &figure, FigureFault fault) {
  Scene scene = spotlight_scene();
  const SpotLight spot = scene.lights[0];  // where the figure says it stands
  if (fault == FigureFault::LightMoved) scene.lights[0].position += glm::vec3(0.3f, 0.0f, 0.0f);
  constexpr int kLightView = 256;
  // The shadow map: the scene's depth from the spotlight, read back from the aux buffer.
  const Scene from_light = figures::seen_from(scene, spot.position, spot.target, spot.cone_degrees,
                                              kLightView);
  render_scene(from_light, project_scene(from_light));
  const figures::Words depth = figures::read_back(kLightView, kLightView, GR_BUFFER_AUXBUFFER);
  // The spotlight map: the beam's cross-section as the texture the passes project.
  constexpr int kBeamSide = 128;
  const std::vector<std::uint8_t> beam = beam_texels(spot, kBeamSide);
  figures::Words beam_words;
  beam_words.width = beam_words.height = kBeamSide;
  for (std::uint8_t v : beam)
    beam_words.data.push_back(static_cast<FxU16>((v >> 3) << 11 | (v >> 2) << 5 | (v >> 3)));
  // Seen from the light, lit by the spotlight alone: where the beam map lets light through.
  Scene spot_only = from_light;
  spot_only.ambient = glm::vec3(0.0f);
  spot_only.background = glm::vec3(0.0f);
  render_scene(spot_only, project_scene(spot_only));
  const figures::Words lit = figures::read_back(kLightView, kLightView);
  // Both: the depth map's shadows under the projected beam, and the same on the Glide passes
  // with Nguyen's projected shadow texture; the truth for the shadow masks.
  figures::Words depth_mask, projected_mask;
  TechniqueOptions options;
  const figures::Words both = figures::render_frame(figures::shadowed_by("depth-map", fault), options, scene, &depth_mask);
  const figures::Words both_glide = figures::render_frame(figures::shadowed_by("projected", fault), options, scene, &projected_mask);

  figure.image = figures::compose(
      {{figures::to_image(depth_as_grey(depth), 1.0f), "THE SHADOW MAP"},
       {figures::magnified(figures::to_image(beam_words, 1.0f), kLightView / kBeamSide), "THE SPOTLIGHT MAP"},
       {figures::to_image(both, figures::kListing4Gamma), "BOTH: DEPTH MAP AND BEAM"},
       {figures::to_image(both_glide, figures::kListing4Gamma), "BOTH ON THE VOODOO PASSES"}});
  figure.shows =
      "Left: the scene's depth from the spotlight (the W-buffer seen from the light, nearer "
      "darker). Second: the spotlight's intensity map, a window gobo in a round beam, 128x128. "
      "Third: the scene with both, the depth-map technique's shadows under the projected beam "
      "with exact distance attenuation (GL texture units 2 and 3). Right: the same light on the "
      "Glide shim, the beam and attenuation in Segal et al.'s passes and the shadows by Nguyen's "
      "projected texture.";

  const auto texel = [&](int x, int y) { return beam[static_cast<std::size_t>(y * kBeamSide + x)]; };
  // Seen from the light, each pixel is the beam texel under it: dark under the bars, lit in the
  // panes (away from the texels' edges, where bilinear filtering blends).
  long compared = 0, agree = 0;
  for (int y = 0; y < kLightView; ++y) {
    for (int x = 0; x < kLightView; ++x) {
      if (depth.at(x, y) == 0xFFFF) continue;  // background
      const int tx = x * kBeamSide / kLightView, ty = y * kBeamSide / kLightView;
      if (tx < 1 || ty < 1 || tx > kBeamSide - 2 || ty > kBeamSide - 2) continue;
      const std::uint8_t t = texel(tx, ty);
      if (t != 0 && t != 255) continue;
      bool uniform = true;
      for (int d = -1; d <= 1; d += 2)
        uniform = uniform && texel(tx + d, ty) == t && texel(tx, ty + d) == t;
      if (!uniform) continue;
      ++compared;
      agree += ((lit.at(x, y) >> 5 & 0x3F) > 4) == (t == 255);
    }
  }
  figure.checks.push_back(figures::check(
      "the spotlight lights the scene through its map: seen from the light, surfaces are lit exactly where the beam map is bright (>= 98% of pixels away from its edges)",
      compared > 10000 && agree * 100 >= compared * 98,
      figures::format("%ld of %ld pixels agree with the beam texel under them", agree, compared)));
  // Both: the shadows are where the ray-cast truth puts them.
  GroundTruth truth;
  std::string error;
  const bool traced = compute_ground_truth(scene, truth, error);
  // Misclassified pixels as a share of the truth's shadowed pixels (the shadows cover about 1%
  // of the visible pixels, so a share of those would let a frame without shadows pass).
  long true_shadow = 0;
  for (std::size_t i = 0; traced && i < truth.shadow.size(); ++i) true_shadow += truth.object[i] >= 0 && truth.shadow[i];
  auto wrong = [&](const figures::Words &mask) {
    long misclassified = 0;
    for (std::size_t i = 0; i < truth.shadow.size() && i < mask.data.size(); ++i) {
      if (truth.object[i] < 0) continue;
      misclassified += (mask.data[i] != 0) != (truth.shadow[i] != 0);
    }
    return true_shadow > 0 ? static_cast<double>(misclassified) / static_cast<double>(true_shadow) : 1.0;
  };
  const double depth_wrong = traced ? wrong(depth_mask) : 1.0, glide_wrong = traced ? wrong(projected_mask) : 1.0;
  figure.checks.push_back(figures::check(
      "shadow and spotlight together: both renderers' shadows match the ray-cast truth (misclassified pixels under 5% of the true shadow's)",
      traced && true_shadow >= 300 && depth_wrong < 0.05 && glide_wrong < 0.05,
      traced ? figures::format("depth map %.2f%%, projected texture %.2f%% of the %ld truly shadowed pixels",
                               100 * depth_wrong, 100 * glide_wrong, true_shadow)
             : error));
}

}  // namespace gs
