// Everitt et al. 2001's figures, drawn by the depth-map technique (depth_map_shadow.h) and, for
// the light's depth, by the Glide shim's own W-buffer seen from the light and read back through
// the LFB. Spaces: world; light view (the light at the origin looking down -z; w is the depth
// along its axis); the light's square view (pixels, y down); the camera's screen; Glide texture
// units (0..256).
#include "figures/figures_kit.h"

#include "measure/ground_truth.h"
#include "measure/metrics.h"
#include "techniques/geometry/projection.h"
#include "techniques/light_passes/scene_pass.h"

#include <glideutl.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace gs {
namespace {

using figures::Words;

constexpr std::size_t kFloor = 0, kBox = 1, kBall = 2;
constexpr int kLightView = 256;

// A box and a ball over a floor under a spotlight from above and to the side.
Scene depth_scene() {
  Scene scene;
  scene.width = kFigureWindowWidth;
  scene.height = kFigureWindowHeight;
  scene.ambient = glm::vec3(0.25f);
  SceneObject floor;
  floor.name = "floor";
  floor.mesh = make_plane(10.0f, 20);
  floor.mesh.set_color(glm::vec3(0.85f, 0.85f, 0.8f));
  floor.casts_shadow = false;
  SceneObject box;
  box.name = "box";
  box.mesh = make_box(glm::vec3(0.5f));
  box.mesh.set_color(glm::vec3(0.8f, 0.35f, 0.25f));
  box.model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(-0.6f, 1.4f, 0.0f));
  SceneObject ball;
  ball.name = "ball";
  ball.mesh = make_sphere(0.45f, 24, 16);
  ball.mesh.set_color(glm::vec3(0.3f, 0.5f, 0.85f));
  ball.model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.9f, 0.45f, 0.6f));
  scene.objects = {floor, box, ball};
  SpotLight light;
  light.position = glm::vec3(1.8f, 7.0f, 1.6f);
  light.target = glm::vec3(0.0f, 0.0f, 0.0f);
  light.cone_degrees = 55.0f;
  light.color = glm::vec3(0.8f);
  scene.lights.push_back(light);
  scene.camera.position = glm::vec3(0.5f, 4.2f, 6.5f);
  scene.camera.target = glm::vec3(0.0f, 0.3f, 0.0f);
  scene.camera.fov_degrees = 45.0f;
  return scene;
}

Scene from_the_light(const Scene &scene) {
  const SpotLight &light = scene.lights[0];
  return figures::seen_from(scene, light.position, light.target, light.cone_degrees, kLightView);
}

// The clip w a W-buffer code stands for: the code is 1/w as a float with 4 exponent and 12
// mantissa bits, the mantissa inverted (the Voodoo's W-buffer format, as the shim stores it).
double clip_w_from_code(FxU16 code) {
  if (code == 0) return 1.0;
  const unsigned exponent = (code - 1u) >> 12;
  const unsigned mantissa = ~(code - 1u) & 0xFFF;
  return std::ldexp(1.0, 13 + static_cast<int>(exponent)) / static_cast<double>(0x1000 | mantissa);
}

// Depth as a grey level, the same scale for the map and for the samples: log2 w from the
// scene's nearest to its farthest point (the W-buffer's codes are nearly log2 w), nearer darker.
struct DepthScale {
  double log_near = 0.0, log_far = 1.0;
  int level(double w) const {  // 0..63, the 565 green field
    const double t = (std::log2(std::max(w, 1e-6)) - log_near) / (log_far - log_near);
    return std::clamp(static_cast<int>(std::lround(t * 63.0)), 0, 63);
  }
};

glm::mat4 light_view(const Scene &scene) {
  const SpotLight &light = scene.lights[0];
  const glm::vec3 axis = glm::normalize(light.target - light.position);
  return glm::lookAt(light.position, light.target,
                     std::abs(axis.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0));
}

DepthScale depth_scale(const Scene &scene) {
  const glm::mat4 view = light_view(scene);
  double nearest = INFINITY, farthest = 0.0;
  for (const SceneObject &object : scene.objects) {
    for (const glm::vec3 &p : object.mesh.positions) {
      const double w = -(view * object.model_to_world * glm::vec4(p, 1.0f)).z;
      if (w <= 0.0) continue;
      nearest = std::min(nearest, w);
      farthest = std::max(farthest, w);
    }
  }
  return {std::log2(nearest), std::log2(farthest)};
}

FxU16 grey565(int level) {  // level 0..63
  return static_cast<FxU16>((level >> 1) << 11 | level << 5 | (level >> 1));
}

// The light's depth buffer: the scene rendered from the light by the W-buffered scene pass and
// the aux buffer read back (the colour buffer under FigureFault::WrongBuffer), as grey levels
// (background white: the far plane).
Words depth_map(const Scene &scene, const DepthScale &scale, FigureFault fault) {
  const Scene light = from_the_light(scene);
  render_scene(light, project_scene(light));
  Words map = figures::read_back(kLightView, kLightView,
                                 fault == FigureFault::WrongBuffer ? GR_BUFFER_BACKBUFFER : GR_BUFFER_AUXBUFFER);
  // Clip w in the camera's units: w = -z_eye times the projection's w row (-m[2][3]).
  const double metres_per_w =
      -1.0 / static_cast<double>(camera_projection(light.camera, light.width, light.height)[2][3]);
  for (FxU16 &code : map.data) {
    code = code == 0xFFFF ? 0xFFFF : grey565(scale.level(clip_w_from_code(code) * metres_per_w));
  }
  return map;
}

// Each sample's distance from the light, from the camera: every vertex coloured by its
// light-view depth and the scene drawn unlit (Gouraud between vertices).
Words sample_depths(const Scene &scene, const DepthScale &scale) {
  Scene grey = scene;
  grey.lights.clear();
  grey.ambient = glm::vec3(1.0f);
  grey.background = glm::vec3(1.0f);
  const glm::mat4 view = light_view(scene);
  for (SceneObject &object : grey.objects) {
    for (std::size_t i = 0; i < object.mesh.positions.size(); ++i) {
      const double w = -(view * object.model_to_world * glm::vec4(object.mesh.positions[i], 1.0f)).z;
      object.mesh.colors[i] = glm::vec3(static_cast<float>(scale.level(w)) / 63.0f);
    }
  }
  render_scene(grey, project_scene(grey));
  return figures::read_back(scene.width, scene.height);
}

// The depth map as a 256x256 RGB 565 texture projected from the light onto the scene (the
// paper's projective (s, t), divided per pixel), drawn unlit.
Words projected_map(const Scene &scene, const Words &map) {
  const FrameGeometry frame = project_scene(scene);
  render_scene(scene, frame);  // the depth buffer; the colour is replaced below
  std::vector<FxU16> texels = map.data;
  GrTexInfo info{GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  const FxU32 address = grTexMinAddress(GR_TMU0);
  grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_POINT_SAMPLED);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                 GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0);
  grDepthBufferFunction(GR_CMP_LEQUAL);
  grDepthMask(FXFALSE);
  const SpotLight &light = scene.lights[0];
  const glm::mat4 light_clip =
      glm::perspective(glm::radians(light.cone_degrees), 1.0f, 0.05f, 1000.0f) * light_view(scene);
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::uvec3 &t : object.object->mesh.triangles) {
      if ((object.outside[t.x] | object.outside[t.y] | object.outside[t.z]) != 0) continue;
      GrVertex v[3] = {object.screen[t.x], object.screen[t.y], object.screen[t.z]};
      const unsigned index[3] = {t.x, t.y, t.z};
      for (int k = 0; k < 3; ++k) {
        const glm::vec4 c = light_clip * glm::vec4(object.world[index[k]], 1.0f);
        v[k].tmuvtx[0].sow = (0.5f * c.x + 0.5f * c.w) * 256.0f * v[k].oow;
        v[k].tmuvtx[0].tow = (0.5f * c.w - 0.5f * c.y) * 256.0f * v[k].oow;
        v[k].tmuvtx[0].oow = c.w * v[k].oow;
      }
      guDrawTriangleWithClip(&v[0], &v[1], &v[2]);
    }
  }
  const Words words = figures::read_back(scene.width, scene.height);
  set_scene_state();
  return words;
}

// On the floor's pixels, where only the casters' shadows fall.
MaskErrors against_truth(const Scene &scene, const Words &mask, GroundTruth &truth) {
  std::string error;
  MaskErrors errors;
  if (!compute_ground_truth(scene, truth, error)) return errors;
  figures::Mask receivers(truth.object.size());
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    receivers[i] = truth.object[i] == static_cast<int>(kFloor);
  }
  return compare_masks(figures::non_zero(mask), truth.shadow, receivers, truth.width, truth.height);
}

int green(FxU16 word) { return (word >> 5) & 0x3F; }

// Across the casters' silhouettes in the light's view: pairs of neighbouring pixels, a caster
// on one side and the floor it hides on the other. The floor there is farther from the light.
FigureCheck check_nearer_darker(const Words &map, const figures::Mask &casters, const figures::Mask &floor) {
  long pairs = 0, darker = 0;
  for (int y = 1; y + 1 < map.height; ++y) {
    for (int x = 1; x + 1 < map.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * map.width + x);
      if (!casters[i]) continue;
      for (const std::size_t j : {i - 1, i + 1, i - static_cast<std::size_t>(map.width),
                                  i + static_cast<std::size_t>(map.width)}) {
        if (!floor[j]) continue;
        ++pairs;
        darker += green(map.data[i]) < green(map.data[j]);
      }
    }
  }
  return figures::check(
      "samples closer to the light are darker: across the casters' silhouettes the caster is darker than the floor behind it (>= 90% of pairs)",
      pairs >= 100 && darker * 10 >= pairs * 9,
      figures::format("%ld of %ld neighbouring caster/floor pairs", darker, pairs));
}

}  // namespace

void figure_everitt_2(Figure &figure, FigureFault fault) {
  const Scene scene = depth_scene();
  const DepthScale scale = depth_scale(scene);
  TechniqueOptions options;
  options.projected.size = 256;
  Words mask;
  const Words frame = figures::render_frame(figures::shadowed_by("depth-map", fault), options, scene, &mask);
  GroundTruth truth;
  const MaskErrors errors = against_truth(scene, mask, truth);
  const Scene light = from_the_light(scene);
  render_scene(light, project_scene(light));
  const Words light_frame = figures::read_back(kLightView, kLightView);
  const Words map = depth_map(scene, scale, fault);
  // Nearer is darker: the casters' samples against the floor's, in the map.
  const figures::Mask casters_seen = [&] {
    figures::Mask m = figures::coverage(light, kBox);
    const figures::Mask ball = figures::coverage(light, kBall);
    for (std::size_t i = 0; i < m.size(); ++i) m[i] |= ball[i];
    return m;
  }();
  const figures::Mask floor_seen = figures::coverage(light, kFloor);
  figure.image = figures::compose({{figures::to_image(frame, figures::kListing4Gamma), "FROM THE EYE"},
                                   {figures::to_image(light_frame, figures::kListing4Gamma), "FROM THE LIGHT"},
                                   {figures::to_image(map, 1.0f), "DEPTH MAP"}});
  figure.shows = "Left: the depth-map technique (plain GL between Glide calls: a 256x256 "
                 "24-bit depth texture, ARB_shadow comparison, percentage-closer filtering). "
                 "Centre: the scene rendered from the light through its 55-degree square "
                 "frustum. Right: the light's depth buffer (the shim's W-buffer, read through "
                 "the LFB) as grey, nearer darker.";
  figure.checks.push_back(check_nearer_darker(map, casters_seen, floor_seen));
  figure.checks.push_back(figures::check(
      "the shadow-mapped scene is shadowed where the light is truly blocked (under 1% of the floor's pixels differ from the ray-cast truth)",
      errors.receiver_pixels > 10000 && errors.misclassified < 0.01,
      figures::format("%.2f%% misclassified (%.2f%% within a pixel of the true edge)",
                      100 * errors.misclassified,
                      100 * (errors.false_light_band + errors.false_shadow_band))));
}

void figure_everitt_4(Figure &figure, FigureFault fault) {
  const Scene scene = depth_scene();
  const DepthScale scale = depth_scale(scene);
  TechniqueOptions options;
  options.projected.size = 256;
  Words mask;
  const Words frame = figures::render_frame(figures::shadowed_by("depth-map", fault), options, scene, &mask);
  const Words distance = sample_depths(scene, scale);
  const Words map = depth_map(scene, scale, FigureFault::None);
  const Words projected = projected_map(scene, map);
  // Where the projected map is nearer than the sample, something stands between the sample
  // and the light: compare with the technique's mask, on the pixels inside the light's cone.
  GroundTruth truth;
  std::string error;
  compute_ground_truth(scene, truth, error);
  // Counted over the pixels where either says shadow (the shadow is about 5% of the cone, so
  // agreement over the whole cone would pass a frame without shadows).
  long nearer = 0, shadowed = 0, both = 0;
  for (std::size_t i = 0; i < projected.data.size() && i < truth.object.size(); ++i) {
    if (truth.object[i] < 0 || truth.reach[i] == LightReach::Outside) continue;
    const bool map_nearer = green(projected.data[i]) + 3 <= green(distance.data[i]);
    nearer += map_nearer;
    shadowed += mask.data[i] != 0;
    both += map_nearer && mask.data[i] != 0;
  }
  const long either = nearer + shadowed - both;
  figure.image = figures::compose({{figures::to_image(frame, figures::kListing4Gamma), "SHADOWED"},
                                   {figures::to_image(distance, 1.0f), "DISTANCE FROM THE LIGHT"},
                                   {figures::to_image(projected, 1.0f), "DEPTH MAP PROJECTED"}});
  figure.shows = "Left: the depth-map technique's frame. Centre: each sample's depth from the "
                 "light (log scale, nearer darker), per vertex and Gouraud shaded. Right: the "
                 "light's depth map (Figure 2) projected onto the scene from the light as a "
                 "texture, point sampled, divided per pixel.";
  figure.checks.push_back(figures::check(
      "comparing the two gives the shadow: where the projected map is nearer than the sample, the technique shadows it, and only there (inside the cone, overlap over union >= 90%)",
      either >= 500 && both * 10 >= either * 9,
      figures::format("overlap %ld / union %ld pixels (map nearer %ld, shadowed %ld)", both, either, nearer, shadowed)));
}

void figure_everitt_5(Figure &figure, FigureFault fault) {
  Scene scene = depth_scene();
  scene.camera.position = glm::vec3(-1.6f, 2.6f, 1.8f);  // close on the box's shadow
  scene.camera.target = glm::vec3(-0.9f, 0.0f, -0.6f);
  scene.camera.fov_degrees = 40.0f;
  TechniqueOptions nearest, linear;
  nearest.projected.size = linear.projected.size = 32;
  nearest.depth_map_linear = false;
  linear.depth_map_linear = fault != FigureFault::PointSampled;
  // The figure shows coarse texels on purpose: the coarse-texel refusal is off.
  nearest.depth_map_largest_footprint_px = linear.depth_map_largest_footprint_px = INFINITY;
  const Words lit = figures::render_frame("none", {}, scene);
  Scene dark = scene;
  dark.lights.clear();
  const Words ambient = figures::render_frame("none", {}, dark);
  const Words frames[2] = {figures::render_frame("depth-map", nearest, scene),
                           figures::render_frame("depth-map", linear, scene)};
  // Floor pixels where only part of the light was taken away (between 15% and 85% of it).
  const figures::Mask floor = figures::coverage(scene, kFloor);
  long partial[2] = {0, 0};
  for (int f = 0; f < 2; ++f) {
    for (std::size_t i = 0; i < lit.data.size(); ++i) {
      if (!floor[i]) continue;
      const double full = figures::darkening(lit.data[i], ambient.data[i]);
      if (full < 0.3) continue;  // little light to take away here
      const double d = figures::darkening(lit.data[i], frames[f].data[i]) / full;
      partial[f] += d > 0.15 && d < 0.85;
    }
  }
  figure.image = figures::compose({{figures::to_image(frames[0], figures::kListing4Gamma), "32X32, NEAREST"},
                                   {figures::to_image(frames[1], figures::kListing4Gamma), "32X32, LINEAR (PCF)"}});
  figure.shows = "The depth-map technique with a 32x32 map, close on the box's shadow. Left: "
                 "GL_NEAREST, one comparison per pixel: blocky, each pixel lit or not. Right: "
                 "GL_LINEAR, the four neighbouring comparisons filtered: the blocks' edges ramp.";
  figure.checks.push_back(figures::check(
      "nearest filtering gives lit-or-shadowed pixels; linear filtering blends the comparisons into intermediate levels",
      partial[1] >= 300 && partial[0] * 10 <= partial[1],
      figures::format("%ld partly shadowed floor pixels with nearest, %ld with linear", partial[0], partial[1])));
}

}  // namespace gs
