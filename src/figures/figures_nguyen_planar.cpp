// Nguyen 1999's figures 2 and 3, drawn by the article's "easy answer", planar projected polygons
// (planar_shadow.h): the shadow polygons, and their edges, sharp however far the shadow is
// stretched, beside the projected texture's. Spaces: world; the camera's screen (pixels, y down).
#include "figures/figures_kit.h"
#include "figures/nguyen_steps.h"

#include "techniques/planar/planar_shadow.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide.h>

#include <algorithm>
#include <cmath>

namespace gs {
namespace {

using figures::check;
using figures::count;
using figures::count_both;
using figures::format;
using figures::kListing4Gamma;
using figures::Mask;
using figures::Words;

// Listing 1's polygons for the scene's light, each in its own flat colour over the scene, drawn
// without the depth test (so a polygon on a receiver hidden from the camera shows too).
Words shadow_polygons(const Scene &scene) {
  const FrameGeometry frame = project_scene(scene);
  render_scene(scene, frame);
  const PlanarShadows shadows = project_and_clip_casters(scene);
  grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
  grCullMode(GR_CULL_DISABLE);
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  std::vector<ClipVertex> polygon, scratch;
  std::vector<GrVertex> screen;
  std::uint32_t hash = 2166136261u;
  for (const ShadowPolygons &light : shadows.lights) {
    for (const ShadowPolygons::Polygon &p : light.polygons) {
      hash = (hash ^ 0x9E3779B9u) * 16777619u;  // a flat colour per polygon
      grConstantColorValue(0xFF000000u | (0x404040u + (hash & 0xBFBFBFu)));
      polygon.clear();
      for (std::uint32_t i = 0; i < p.count; ++i) polygon.push_back({{}, light.vertices[p.first + i], {}});
      project_camera_polygon(frame, scene, polygon, scratch, screen);
      if (screen.size() >= 3) draw_fan(screen);
    }
  }
  const Words words = figures::read_back(scene.width, scene.height);
  set_scene_state();
  return words;
}

// How wide the shadow's edge is, in pixels: the pixels darkened by part of the technique's full
// darkening (15% to 85% of it, the full darkening being the median inside the shadow) over the
// length of the edge (shadowed pixels, past half the full darkening, with an unshadowed
// 4-neighbour). Only pixels of `receiver` bright enough to measure a ratio count.
struct EdgeWidth {
  long partial = 0, edge = 0;
  double width() const { return edge > 0 ? static_cast<double>(partial) / static_cast<double>(edge) : 0.0; }
};
EdgeWidth edge_width(const Words &unshadowed, const Words &shadowed, const Mask &receiver) {
  const int w = unshadowed.width, h = unshadowed.height;
  std::vector<double> darkening(unshadowed.data.size(), 0.0), inside;
  for (std::size_t i = 0; i < darkening.size(); ++i) {
    if (!receiver[i] || ((unshadowed.data[i] >> 5) & 0x3F) < 16) continue;
    darkening[i] = figures::darkening(unshadowed.data[i], shadowed.data[i]);
    if (darkening[i] > 0.2) inside.push_back(darkening[i]);
  }
  EdgeWidth result;
  if (inside.empty()) return result;
  std::nth_element(inside.begin(), inside.begin() + static_cast<std::ptrdiff_t>(inside.size() / 2), inside.end());
  const double full = inside[inside.size() / 2];
  auto shadowed_at = [&](int x, int y) { return darkening[static_cast<std::size_t>(y * w + x)] > 0.5 * full; };
  for (int y = 1; y + 1 < h; ++y) {
    for (int x = 1; x + 1 < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * w + x);
      if (!receiver[i] || ((unshadowed.data[i] >> 5) & 0x3F) < 16) continue;
      const double d = darkening[i] / full;
      result.partial += d > 0.15 && d < 0.85;
      result.edge += shadowed_at(x, y) && (!shadowed_at(x - 1, y) || !shadowed_at(x + 1, y) ||
                                           !shadowed_at(x, y - 1) || !shadowed_at(x, y + 1));
    }
  }
  return result;
}

}  // namespace

void figure_nguyen_2(Figure &figure, FigureFault fault) {
  const Scene scene = figures::article_scene();
  Words mask;
  const Words frame = figures::render_frame(figures::shadowed_by("planar", fault), {}, scene, &mask);
  const Words polygons = shadow_polygons(scene);
  // Against the ray-cast shadow of the mesh the polygons are projected from (the shadow mesh),
  // on the floor and the step; misclassified pixels as a share of the truly shadowed ones.
  Mask truth, receivers;
  const bool traced = figures::true_shadow(scene, truth, receivers);
  const Mask ours = figures::non_zero(mask);
  long wrong = 0, shadowed = 0;
  for (std::size_t i = 0; traced && i < truth.size(); ++i) {
    if (!receivers[i]) continue;
    shadowed += truth[i] != 0;
    wrong += (ours[i] != 0) != (truth[i] != 0);
  }
  figure.image = figures::compose({{figures::to_image(polygons, kListing4Gamma), "THE SHADOW POLYGONS"},
                                   {figures::to_image(frame, kListing4Gamma), "DRAWN AS SHADOWS"}});
  figure.shows = "Listing 1 on our scene: each triangle of the fighter's shadow mesh facing the "
                 "light projected onto the plane of each floor and step triangle and clipped to "
                 "it. Left: the polygons, each in its own colour, over the scene (drawn without "
                 "the depth test). Right: the planar technique's frame, the polygons drawn dark "
                 "at the light's shadow strength.";
  figure.checks.push_back(check(
      "the projected polygons are the shadow: on the floor and the step they differ from the ray-cast shadow on fewer pixels than 5% of it",
      traced && shadowed >= 1000 && wrong * 20 < shadowed,
      format("%ld pixels differ, %ld truly shadowed", wrong, shadowed)));
}

void figure_nguyen_3(Figure &figure, FigureFault fault) {
  // The light low and far to the side: the fighter's shadow stretches across the floor; the
  // camera looks at its far part, beside the step.
  Scene scene = figures::article_scene();
  scene.lights[0].position = glm::vec3(-4.5f, 2.4f, 1.0f);
  scene.lights[0].target = glm::vec3(0.0f, 0.9f, 0.0f);
  scene.camera.position = glm::vec3(2.4f, 1.8f, 1.6f);
  scene.camera.target = glm::vec3(2.6f, 0.0f, -0.5f);
  scene.camera.fov_degrees = 40.0f;
  TechniqueOptions projected;
  projected.projected.size = 64;
  projected.projected.bilinear = fault != FigureFault::PointSampled;
  // The figure shows stretched texels on purpose: the coarse-texel refusal is off.
  projected.projected.largest_texel_footprint_px = INFINITY;
  const Words unshadowed = figures::render_frame("none", {}, scene);
  const Words planar = figures::render_frame(figures::shadowed_by("planar", fault), {}, scene);
  const Words textured = figures::render_frame("projected", projected, scene);
  const Mask floor = figures::coverage(scene, figures::kFloor);
  const EdgeWidth sharp = edge_width(unshadowed, planar, floor);
  const EdgeWidth soft = edge_width(unshadowed, textured, floor);
  figure.image = figures::compose({{figures::to_image(planar, kListing4Gamma), "PLANAR POLYGONS"},
                                   {figures::to_image(textured, kListing4Gamma), "PROJECTED TEXTURE 64X64"}});
  figure.shows = "The light low to the fighter's left, so his shadow stretches across the floor. "
                 "Left: the planar polygons, their edges sharp along the whole shadow. Right: the "
                 "projected shadow texture (64x64, bilinear, as Figure 15's): stretched, each "
                 "texel covers several pixels, so the edge ramps over several pixels and steps "
                 "where texel rows meet it.";
  figure.checks.push_back(check(
      "planar edges stay sharp when the shadow is stretched (edge under 0.5 pixel wide) where the projected texture's ramps (at least 1.5 pixels, 3 times the planar one)",
      sharp.edge >= 200 && soft.edge >= 200 && sharp.width() < 0.5 && soft.width() >= 1.5 &&
          soft.width() >= 3.0 * sharp.width(),
      format("edge width: planar %.2f px (%ld partial / %ld edge pixels), projected %.2f px (%ld / %ld)",
             sharp.width(), sharp.partial, sharp.edge, soft.width(), soft.partial, soft.edge)));
}

}  // namespace gs
