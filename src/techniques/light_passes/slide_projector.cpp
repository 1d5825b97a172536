// The slide-projector passes. Spaces: world; projector view and clip (GL convention, the
// projector at the origin looking down -z); Glide screen; slide texture units (0..256).
#include "techniques/light_passes/slide_projector.h"

#include "scene/lighting.h"
#include "scene/spotlight.h"

#include <glideutl.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace gs {
namespace {

constexpr int kAttenuationRows = 32;  // the ramp's rows: aspect 8x1, the widest

using VertexColor = std::function<glm::vec3(const ProjectedObject &, unsigned)>;  // 0..255

// Every triangle of the scene with the step-4 screen vertices where they need no clipping, so
// each pass sends identical vertices and EQUAL passes; `color` gives the iterated colour.
void draw_scene_pass(const Scene &scene, const FrameGeometry &frame, const VertexColor &color) {
  std::vector<ClipVertex> polygon, scratch;
  std::vector<GrVertex> screen;
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::uvec3 &t : object.object->mesh.triangles) {
      const unsigned index[3] = {t.x, t.y, t.z};
      const unsigned outside = object.outside[t.x] | object.outside[t.y] | object.outside[t.z];
      if (outside == 0) {
        GrVertex v[3];
        for (int k = 0; k < 3; ++k) {
          v[k] = object.screen[index[k]];
          const glm::vec3 c = color(object, index[k]);
          v[k].r = c.r, v[k].g = c.g, v[k].b = c.b;
        }
        guDrawTriangleWithClip(&v[0], &v[1], &v[2]);
        continue;
      }
      if ((object.outside[t.x] & object.outside[t.y] & object.outside[t.z]) != 0) continue;
      polygon.clear();
      for (unsigned i : index) polygon.push_back({{}, object.world[i], glm::vec4(color(object, i), 0.0f)});
      project_camera_polygon(frame, scene, polygon, scratch, screen);
      for (std::size_t i = 0; i < screen.size(); ++i) {
        screen[i].r = polygon[i].extra.r, screen[i].g = polygon[i].extra.g, screen[i].b = polygon[i].extra.b;
      }
      draw_fan(screen);
    }
  }
}

// What a projected pass sends for each vertex: its colour and texture coordinates, from the
// vertex's world position and unit world normal.
using ProjectedVertex =
    std::function<void(GrVertex &, const glm::vec3 &world, const glm::vec3 &normal)>;

// One pass over the surfaces `light` sees: triangles facing it, in front of its near plane.
// Triangles crossing that plane are clipped there (negative projection), which changes their
// vertices, so those few pass LEQUAL with a small bias instead of EQUAL.
void draw_projected_pass(const Scene &scene, const FrameGeometry &frame, const SpotLight &light,
                         const ProjectedVertex &setup) {
  const glm::mat4 view = light_view(light);
  const glm::vec4 in_front{0.0f, 0.0f, -1.0f, -kLightNearPlane};  // light view: -z >= near
  std::vector<ClipVertex> polygon, scratch;
  std::vector<GrVertex> screen;
  std::vector<std::vector<GrVertex>> clipped;
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::uvec3 &t : object.object->mesh.triangles) {
      const unsigned index[3] = {t.x, t.y, t.z};
      const glm::vec3 &a = object.world[t.x], &b = object.world[t.y], &c = object.world[t.z];
      if (glm::dot(glm::cross(b - a, c - a), light.position - a) <= 0.0f) continue;  // faces away
      bool all_in_front = true, any_in_front = false;
      for (unsigned i : index) {
        const bool front = -(view * glm::vec4(object.world[i], 1.0f)).z >= kLightNearPlane;
        all_in_front = all_in_front && front;
        any_in_front = any_in_front || front;
      }
      if (!any_in_front) continue;  // wholly behind the light
      const unsigned outside = object.outside[t.x] | object.outside[t.y] | object.outside[t.z];
      if (all_in_front && outside == 0) {
        GrVertex v[3];
        for (int k = 0; k < 3; ++k) {
          v[k] = object.screen[index[k]];
          setup(v[k], object.world[index[k]], object.normal[index[k]]);
        }
        guDrawTriangleWithClip(&v[0], &v[1], &v[2]);
        continue;
      }
      polygon.clear();
      for (unsigned i : index)
        polygon.push_back({view * glm::vec4(object.world[i], 1.0f), object.world[i],
                           glm::vec4(object.normal[i], 0.0f)});
      clip_polygon(polygon, in_front, scratch);
      if (polygon.size() < 3) continue;
      project_camera_polygon(frame, scene, polygon, scratch, screen);
      for (std::size_t i = 0; i < screen.size(); ++i) {
        const glm::vec3 normal(polygon[i].extra);
        setup(screen[i], polygon[i].world, glm::length(normal) > 0.0f ? glm::normalize(normal) : normal);
      }
      if (screen.size() >= 3) clipped.push_back(screen);
    }
  }
  grDepthBufferFunction(GR_CMP_LEQUAL);
  grDepthBiasLevel(-8);
  for (const std::vector<GrVertex> &fan : clipped) draw_fan(fan);
  grDepthBiasLevel(0);
  grDepthBufferFunction(GR_CMP_EQUAL);
}

// The paper's projective texture coordinates for a texture spanning the light's cone: s/w, t/w
// and w_l/w, which the TMU divides per pixel (GR_STWHINT_W_DIFF_TMU0). Texture units 0..256.
void set_projective_coordinates(GrVertex &v, const glm::mat4 &light_clip, const glm::vec3 &world) {
  const glm::vec4 c = light_clip * glm::vec4(world, 1.0f);
  v.tmuvtx[0].sow = (0.5f * c.x + 0.5f * c.w) * 256.0f * v.oow;
  v.tmuvtx[0].tow = (0.5f * c.w - 0.5f * c.y) * 256.0f * v.oow;
  v.tmuvtx[0].oow = c.w * v.oow;
}

void set_iterated_color(GrVertex &v, const glm::vec3 &color) {
  const glm::vec3 c = glm::clamp(color, 0.0f, 1.0f) * 255.0f;
  v.r = c.r, v.g = c.g, v.b = c.b;
}

void use_texture(FxU32 address, GrLOD_t lod, GrAspectRatio_t aspect, GrTextureFormat_t format,
                 void *texels) {
  GrTexInfo info{lod, lod, aspect, format, texels};
  grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
}

void use_beam_texture(const SpotLight &light) {
  std::vector<std::uint8_t> texels = beam_texels(light, kBeamMapSide);
  use_texture(kProjectiveTextureAddress, GR_LOD_128, GR_ASPECT_1x1, GR_TEXFMT_INTENSITY_8,
              texels.data());
}

// The nearest and farthest light-space depth of the frame's vertices in front of `light`.
std::pair<float, float> depth_range(const FrameGeometry &frame, const SpotLight &light) {
  float nearest = kLightFarPlane, farthest = kLightNearPlane;
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::vec3 &world : object.world) {
      const float d = axial_distance(light, world);
      if (d < kLightNearPlane) continue;
      nearest = std::min(nearest, d);
      farthest = std::max(farthest, d);
    }
  }
  return {std::min(nearest, farthest), std::max(farthest, nearest + 1e-3f)};
}

// The spotlight whose attenuation is exact per pixel: formed first, into the cleared (black)
// accumulation, as a product of two passes, since one texture unit cannot sample the beam and
// the attenuation at once: light x diffuse x attenuation(depth) replaces the black, then the
// frame buffer is multiplied by the beam map.
void form_exact_spotlight(const Scene &scene, const FrameGeometry &frame, const SpotLight &light) {
  // The attenuation as a 256 x 32 texture whose s runs over the frame's light-space depths; s
  // is affine in the world, so the TMU's perspective-correct iteration (by the eye's w) gives
  // each pixel its own depth, hence attenuation(depth) per pixel up to the texel spacing.
  // Plain variables, not a structured binding: C++17 lambdas cannot capture bindings (clang).
  const std::pair<float, float> range = depth_range(frame, light);
  const float nearest = range.first, farthest = range.second;
  std::vector<std::uint8_t> ramp = attenuation_texels(light, nearest, farthest, kAttenuationMapWidth);
  std::vector<std::uint8_t> texels(ramp.size() * kAttenuationRows);
  for (int row = 0; row < kAttenuationRows; ++row)
    std::copy(ramp.begin(), ramp.end(), texels.begin() + row * kAttenuationMapWidth);
  use_texture(kProjectiveTextureAddress, GR_LOD_256, GR_ASPECT_8x1, GR_TEXFMT_INTENSITY_8,
              texels.data());
  grHints(GR_HINT_STWHINT, 0);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                 GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  const float texels_per_metre = static_cast<float>(kAttenuationMapWidth) / (farthest - nearest);
  draw_projected_pass(scene, frame, light, [&](GrVertex &v, const glm::vec3 &world,
                                               const glm::vec3 &normal) {
    set_iterated_color(v, vertex_light_term(light, world, normal, true));
    const float s = (axial_distance(light, world) - nearest) * texels_per_metre;  // texels
    v.tmuvtx[0].sow = s * v.oow;
    v.tmuvtx[0].tow = 0.5f * kAttenuationRows * v.oow;
    v.tmuvtx[0].oow = v.oow;
  });

  use_beam_texture(light);
  grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                 GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  grAlphaBlendFunction(GR_BLEND_ZERO, GR_BLEND_SRC_COLOR, GR_BLEND_ONE, GR_BLEND_ZERO);
  const glm::mat4 light_clip = light_projection(light) * light_view(light);
  draw_projected_pass(scene, frame, light, [&](GrVertex &v, const glm::vec3 &world,
                                               const glm::vec3 &) {
    set_projective_coordinates(v, light_clip, world);
  });
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ZERO);
}

// A spotlight with a beam map and no per-pixel attenuation: added in one pass, its per-vertex
// light times the projected beam.
void add_spotlight(const Scene &scene, const FrameGeometry &frame, const SpotLight &light) {
  use_beam_texture(light);
  grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                 GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  const glm::mat4 light_clip = light_projection(light) * light_view(light);
  draw_projected_pass(scene, frame, light, [&](GrVertex &v, const glm::vec3 &world,
                                               const glm::vec3 &normal) {
    set_iterated_color(v, vertex_light_term(light, world, normal, false));
    set_projective_coordinates(v, light_clip, world);
  });
}

// The paper's second pass for one slide projector: its slide, times the projector's colour (the
// constant colour), added where the projector sees the surface.
void add_slide(const Scene &scene, const FrameGeometry &frame, const SpotLight &projector) {
  int side = 0;
  std::vector<FxU16> texels = slide_texels(projector, side);
  use_texture(kProjectiveTextureAddress, side == 128 ? GR_LOD_128 : GR_LOD_64, GR_ASPECT_1x1,
              GR_TEXFMT_RGB_565, texels.data());
  grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                 GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  const glm::vec3 c = glm::clamp(projector.color, 0.0f, 1.0f) * 255.0f;
  grConstantColorValue(static_cast<GrColor_t>(c.r) << 16 | static_cast<GrColor_t>(c.g) << 8 |
                       static_cast<GrColor_t>(c.b));
  const glm::mat4 light_clip = light_projection(projector) * light_view(projector);
  draw_projected_pass(scene, frame, projector, [&](GrVertex &v, const glm::vec3 &world,
                                                   const glm::vec3 &) {
    set_projective_coordinates(v, light_clip, world);
  });
}

}  // namespace

bool needs_projective_passes(const Scene &scene) {
  return std::any_of(scene.lights.begin(), scene.lights.end(), [](const SpotLight &light) {
    return light.is_projector() || light.has_beam_map();
  });
}

void render_scene_with_projectors(const Scene &scene, const FrameGeometry &frame) {
  set_scene_state();
  const glm::vec3 background = glm::clamp(scene.background, 0.0f, 1.0f) * 255.0f;
  grBufferClear(static_cast<GrColor_t>(background.r) << 16 |
                    static_cast<GrColor_t>(background.g) << 8 | static_cast<GrColor_t>(background.b),
                0, GR_WDEPTHVALUE_FARTHEST);
  // Pass 1: depth, and black where the surfaces are: the light accumulates from there.
  draw_scene_pass(scene, frame, [](const ProjectedObject &, unsigned) { return glm::vec3(0.0f); });
  grDepthMask(FXFALSE);
  grDepthBufferFunction(GR_CMP_EQUAL);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  // Pass 2: the light reaching each visible surface, before its colour. The exact spotlight
  // first, as it needs the black accumulation; then, added: ambient and the lights shaded per
  // vertex (white surfaces), each spotlight with a beam map, each projector's slide.
  const auto exact = std::find_if(scene.lights.begin(), scene.lights.end(), [](const SpotLight &l) {
    return l.has_beam_map() && l.attenuation.mode == AttenuationMode::PerPixel;
  });
  if (exact != scene.lights.end()) form_exact_spotlight(scene, frame, *exact);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ZERO);
  Scene vertex_lights;  // the lights without a projected texture, and the ambient
  vertex_lights.ambient = scene.ambient;
  for (const SpotLight &light : scene.lights)
    if (!light.is_projector() && !light.has_beam_map()) vertex_lights.lights.push_back(light);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  draw_scene_pass(scene, frame, [&](const ProjectedObject &object, unsigned i) {
    return shade_vertex(vertex_lights, object.world[i], object.normal[i], glm::vec3(1.0f)) * 255.0f;
  });
  for (auto light = scene.lights.begin(); light != scene.lights.end(); ++light) {
    if (light->has_beam_map() && light != exact) add_spotlight(scene, frame, *light);
    if (light->is_projector()) add_slide(scene, frame, *light);
  }
  grHints(GR_HINT_STWHINT, 0);
  // Pass 3: modulate by the surface colour: dst = dst x src (dst factor SRC_COLOR).
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  grAlphaBlendFunction(GR_BLEND_ZERO, GR_BLEND_SRC_COLOR, GR_BLEND_ONE, GR_BLEND_ZERO);
  draw_scene_pass(scene, frame, [](const ProjectedObject &object, unsigned i) {
    return glm::clamp(object.object->mesh.colors[i], 0.0f, 1.0f) * 255.0f;
  });
  set_scene_state();
}

}  // namespace gs
