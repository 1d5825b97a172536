// The slide-projector passes. Spaces: world; projector view and clip (GL convention, the
// projector at the origin looking down -z); Glide screen; slide texture units (0..256).
#include "slide_projector.h"

#include "lighting.h"

#include <glideutl.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace gs {
namespace {

constexpr int kSlideSide = 64;
constexpr FxU32 kSlideAddress = 0x180000;  // TMU memory above the shadow textures' usual range

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

// The paper's second pass for one projector: its slide added where the projector sees the
// surface. Triangles crossing the projector's plane are clipped there (negative projection),
// which changes their vertices, so those few pass LEQUAL with a small bias instead of EQUAL.
void add_slide(const Scene &scene, const FrameGeometry &frame, const SpotLight &projector) {
  const glm::mat4 view = glm::lookAt(projector.position, projector.target,
                                     std::abs(glm::normalize(projector.target - projector.position).y) > 0.99f
                                         ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0));
  const float near_plane = 0.05f;
  const glm::mat4 projection = glm::perspective(glm::radians(projector.cone_degrees), 1.0f,
                                                near_plane, 1000.0f);
  const glm::mat4 projector_clip = projection * view;
  auto set_stq = [&](GrVertex &v, const glm::vec3 &world) {
    // The paper's projective coordinates: s/w, t/w and w_l/w, divided per pixel by the TMU.
    const glm::vec4 c = projector_clip * glm::vec4(world, 1.0f);
    v.tmuvtx[0].sow = (0.5f * c.x + 0.5f * c.w) * 256.0f * v.oow;
    v.tmuvtx[0].tow = (0.5f * c.w - 0.5f * c.y) * 256.0f * v.oow;
    v.tmuvtx[0].oow = c.w * v.oow;
  };
  const glm::vec4 in_front{0.0f, 0.0f, -1.0f, -near_plane};  // projector view: -z >= near
  std::vector<ClipVertex> polygon, scratch;
  std::vector<GrVertex> screen;
  std::vector<std::vector<GrVertex>> clipped;
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::uvec3 &t : object.object->mesh.triangles) {
      const unsigned index[3] = {t.x, t.y, t.z};
      const glm::vec3 &a = object.world[t.x], &b = object.world[t.y], &c = object.world[t.z];
      if (glm::dot(glm::cross(b - a, c - a), projector.position - a) <= 0.0f) continue;  // faces away
      bool all_in_front = true, any_in_front = false;
      for (unsigned i : index) {
        const bool front = -(view * glm::vec4(object.world[i], 1.0f)).z >= near_plane;
        all_in_front = all_in_front && front;
        any_in_front = any_in_front || front;
      }
      if (!any_in_front) continue;  // wholly behind the projector
      const unsigned outside = object.outside[t.x] | object.outside[t.y] | object.outside[t.z];
      if (all_in_front && outside == 0) {
        GrVertex v[3];
        for (int k = 0; k < 3; ++k) {
          v[k] = object.screen[index[k]];
          set_stq(v[k], object.world[index[k]]);
        }
        guDrawTriangleWithClip(&v[0], &v[1], &v[2]);
        continue;
      }
      polygon.clear();
      for (unsigned i : index) polygon.push_back({view * glm::vec4(object.world[i], 1.0f), object.world[i], {}});
      clip_polygon(polygon, in_front, scratch);
      if (polygon.size() < 3) continue;
      project_camera_polygon(frame, scene, polygon, scratch, screen);
      for (std::size_t i = 0; i < screen.size(); ++i) set_stq(screen[i], polygon[i].world);
      if (screen.size() >= 3) clipped.push_back(screen);
    }
  }
  grDepthBufferFunction(GR_CMP_LEQUAL);
  grDepthBiasLevel(-8);
  for (const std::vector<GrVertex> &fan : clipped) draw_fan(fan);
  grDepthBiasLevel(0);
  grDepthBufferFunction(GR_CMP_EQUAL);
}

std::uint16_t rgb565(float r, float g, float b) {
  return static_cast<std::uint16_t>(static_cast<int>(r * 31.0f) << 11 |
                                    static_cast<int>(g * 63.0f) << 5 | static_cast<int>(b * 31.0f));
}

}  // namespace

bool is_slide_pattern(const std::string &name) {
  return name == "checker" || name == "rings" || name == "grid";
}

std::vector<FxU16> slide_texels(const std::string &name) {
  std::vector<FxU16> texels(kSlideSide * kSlideSide, 0);
  for (int y = 1; y < kSlideSide - 1; ++y) {
    for (int x = 1; x < kSlideSide - 1; ++x) {
      // Slide coordinates in [-1, 1], the centre at 0.
      const float u = (static_cast<float>(x) + 0.5f) / kSlideSide * 2.0f - 1.0f;
      const float v = (static_cast<float>(y) + 0.5f) / kSlideSide * 2.0f - 1.0f;
      std::uint16_t texel = 0;
      if (name == "checker") {
        texel = ((x / 8 + y / 8) % 2 == 0) ? rgb565(1, 1, 1) : 0;
      } else if (name == "rings") {
        const float r = std::sqrt(u * u + v * v);
        texel = r < 1.0f && static_cast<int>(r * 5.0f) % 2 == 0 ? rgb565(1.0f, 0.8f, 0.3f) : 0;
      } else {
        texel = (x % 8 == 0 || y % 8 == 0) ? rgb565(0.3f, 1.0f, 0.4f) : rgb565(0.1f, 0.1f, 0.4f);
      }
      texels[static_cast<std::size_t>(y * kSlideSide + x)] = texel;
    }
  }
  return texels;
}

bool has_slide_projectors(const Scene &scene) {
  return std::any_of(scene.lights.begin(), scene.lights.end(),
                     [](const SpotLight &light) { return light.is_projector(); });
}

void render_scene_with_projectors(const Scene &scene, const FrameGeometry &frame) {
  set_scene_state();
  grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST);
  // Pass 1: depth only.
  grColorMask(FXFALSE, FXFALSE);
  draw_scene_pass(scene, frame, [](const ProjectedObject &, unsigned) { return glm::vec3(0.0f); });
  grColorMask(FXTRUE, FXFALSE);
  grDepthMask(FXFALSE);
  grDepthBufferFunction(GR_CMP_EQUAL);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ZERO);
  // Pass 2: the light reaching each visible surface, before its colour: ambient and the other
  // lights (white surfaces), then each projector's slide.
  draw_scene_pass(scene, frame, [&](const ProjectedObject &object, unsigned i) {
    return shade_vertex(scene, object.world[i], object.normal[i], glm::vec3(1.0f)) * 255.0f;
  });
  grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  // Colour = slide x the projector's colour (the constant colour).
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                 GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  for (const SpotLight &light : scene.lights) {
    if (!light.is_projector()) continue;
    std::vector<FxU16> texels = slide_texels(light.slide);
    GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
    grTexDownloadMipMap(GR_TMU0, kSlideAddress, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexSource(GR_TMU0, kSlideAddress, GR_MIPMAPLEVELMASK_BOTH, &info);
    const glm::vec3 c = glm::clamp(light.color, 0.0f, 1.0f) * 255.0f;
    grConstantColorValue(static_cast<GrColor_t>(c.r) << 16 | static_cast<GrColor_t>(c.g) << 8 |
                         static_cast<GrColor_t>(c.b));
    add_slide(scene, frame, light);
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
