// The scene pass: lighting and camera projection per vertex, then Gouraud triangles.
#include "techniques/light_passes/scene_pass.h"

#include "scene/lighting.h"
#include "techniques/light_passes/slide_projector.h"

#include <glideutl.h>

namespace gs {
namespace {

unsigned outcode(const glm::vec4 &clip, const std::vector<glm::vec4> &planes) {
  unsigned bits = 0;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    if (glm::dot(planes[i], clip) < 0.0f) bits |= 1u << i;
  }
  return bits;
}

}  // namespace

FrameGeometry project_scene(const Scene &scene) {
  const std::vector<glm::vec4> planes = camera_clip_planes(8.0f);
  FrameGeometry frame;
  frame.view_projection = camera_projection(scene.camera, scene.width, scene.height) *
                          camera_view(scene.camera);
  frame.objects.reserve(scene.objects.size());
  for (const SceneObject &object : scene.objects) {
    ProjectedObject projected;
    projected.object = &object;
    const Mesh &mesh = object.mesh;
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(object.model_to_world)));
    const std::size_t n = mesh.positions.size();
    projected.world.resize(n);
    projected.normal.resize(n);
    projected.outside.resize(n);
    projected.screen.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const glm::vec3 world = glm::vec3(object.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
      const glm::vec3 normal = glm::normalize(normal_matrix * mesh.normals[i]);
      projected.world[i] = world;
      projected.normal[i] = normal;
      const glm::vec4 clip = frame.view_projection * glm::vec4(world, 1.0f);  // camera clip space
      projected.outside[i] = outcode(clip, planes);
      if (projected.outside[i] == 0) {
        GrVertex &v = projected.screen[i];
        v = to_screen(clip, scene.width, scene.height);
        const glm::vec3 color = shade_vertex(scene, world, normal, mesh.colors[i]) * 255.0f;
        v.r = color.r, v.g = color.g, v.b = color.b;
      }
    }
    frame.objects.push_back(std::move(projected));
  }
  return frame;
}

void project_camera_polygon(const FrameGeometry &frame, const Scene &scene,
                            std::vector<ClipVertex> &polygon, std::vector<ClipVertex> &scratch,
                            std::vector<GrVertex> &screen) {
  static const std::vector<glm::vec4> planes = camera_clip_planes(8.0f);
  screen.clear();
  for (ClipVertex &v : polygon) v.clip = frame.view_projection * glm::vec4(v.world, 1.0f);
  for (const glm::vec4 &plane : planes) {
    clip_polygon(polygon, plane, scratch);
    if (polygon.size() < 3) return;
  }
  for (const ClipVertex &v : polygon) screen.push_back(to_screen(v.clip, scene.width, scene.height));
}

void draw_fan(const std::vector<GrVertex> &polygon) {
  for (std::size_t i = 2; i < polygon.size(); ++i) {
    guDrawTriangleWithClip(&polygon[0], &polygon[i - 1], &polygon[i]);
  }
}

void draw_object_triangle(const FrameGeometry &frame, const Scene &scene,
                          const ProjectedObject &object, const glm::uvec3 &triangle) {
  const unsigned a = object.outside[triangle.x], b = object.outside[triangle.y],
                 c = object.outside[triangle.z];
  if ((a | b | c) == 0) {
    guDrawTriangleWithClip(&object.screen[triangle.x], &object.screen[triangle.y],
                           &object.screen[triangle.z]);
    return;
  }
  if ((a & b & c) != 0) return;  // wholly outside one plane
  std::vector<ClipVertex> polygon, scratch;
  for (unsigned index : {triangle.x, triangle.y, triangle.z}) {
    const glm::vec3 color = shade_vertex(scene, object.world[index], object.normal[index],
                                         object.object->mesh.colors[index]) * 255.0f;
    polygon.push_back({{}, object.world[index], glm::vec4(color, 0.0f)});
  }
  std::vector<GrVertex> screen;
  project_camera_polygon(frame, scene, polygon, scratch, screen);
  for (std::size_t i = 0; i < screen.size(); ++i) {
    screen[i].r = polygon[i].extra.r, screen[i].g = polygon[i].extra.g, screen[i].b = polygon[i].extra.b;
  }
  draw_fan(screen);
}

void set_scene_state() {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LEQUAL);
  grDepthMask(FXTRUE);
  grCullMode(GR_CULL_POSITIVE);  // counter-clockwise in the world is clockwise on a y-down screen
  grDitherMode(GR_DITHER_DISABLE);
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  guAlphaSource(GR_ALPHASOURCE_CC_ALPHA);
  grHints(GR_HINT_STWHINT, 0);
}

void render_scene(const Scene &scene, const FrameGeometry &frame) {
  if (needs_projective_passes(scene)) {
    render_scene_with_projectors(scene, frame);
    return;
  }
  set_scene_state();
  const glm::vec3 background = glm::clamp(scene.background, 0.0f, 1.0f) * 255.0f;
  const GrColor_t clear = (static_cast<GrColor_t>(background.r) << 16) |
                          (static_cast<GrColor_t>(background.g) << 8) |
                          static_cast<GrColor_t>(background.b);
  grBufferClear(clear, 0, GR_WDEPTHVALUE_FARTHEST);
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::uvec3 &triangle : object.object->mesh.triangles) {
      draw_object_triangle(frame, scene, object, triangle);
    }
  }
}

void render_scene_depth(const Scene &scene, const FrameGeometry &frame) {
  set_scene_state();
  grColorMask(FXFALSE, FXFALSE);
  grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST);  // depth only: colour writes are off
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::uvec3 &triangle : object.object->mesh.triangles) {
      draw_object_triangle(frame, scene, object, triangle);
    }
  }
  grColorMask(FXTRUE, FXFALSE);
}

}  // namespace gs
