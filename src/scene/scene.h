// A scene: meshes placed in the world, spotlights, a camera and the screen size. Everything a
// technique needs to render a frame; built in code (the demo) or read from a JSON scene file.
#pragma once

#include "scene/mesh.h"

#include <memory>
#include <string>
#include <vector>

namespace gs {

struct SceneObject {
  std::string name;
  Mesh mesh;                       // model space
  // A simplified caster for the shadow pass; empty: use `mesh`. Only the figures of the
  // article's pipeline give one: its shadow is not the object's (fight_scene.cpp).
  Mesh shadow_mesh;
  glm::mat4 model_to_world{1.0f};
  bool casts_shadow = true;
  bool receives_shadow = true;
};

// An image a light projects (a slide, or a beam's cross-section) read from a file: RGB 0..1, a
// square power-of-two side, row 0 at the top.
struct ProjectedImage {
  int side = 0;
  std::vector<glm::vec3> rgb;
};

// How a spotlight's light falls off with distance (Segal et al. 3.2): none, evaluated per vertex
// and interpolated (cheap), or per pixel as a function of the light-space depth (exact; the
// Glide renderer then needs the frame's cleared accumulation, so one such light per scene).
enum class AttenuationMode { None, PerVertex, PerPixel };
struct DistanceAttenuation {
  AttenuationMode mode = AttenuationMode::None;
  float constant = 1.0f, linear = 0.0f, quadratic = 0.0f;  // 1 / (c + l d + q d^2), d in metres
};

struct SpotLight {
  glm::vec3 position{0.0f, 5.0f, 0.0f};  // world
  glm::vec3 target{0.0f};                // world
  float cone_degrees = 60.0f;            // full angle of the beam
  glm::vec3 color{1.0f};
  float shadow_strength = 170.0f / 255.0f;  // the article's iterated alpha 170
  int shadow_size = 256;                    // shadow texture side, texels
  // Non-empty: a slide projector (Segal et al. 1992) showing this built-in slide (see
  // slide_projector.h) or `slide_image`; it lights only through its slide and casts no shadow.
  std::string slide;
  std::shared_ptr<const ProjectedImage> slide_image;  // set when `slide` names an image file
  // Empty: the smooth cone (spot_factor in lighting.h), shaded per vertex. Otherwise the beam's
  // cross-section (spotlight.h: round, square, gobo, lens, or `beam_image`), which the Glide
  // scene pass projects as a texture per pixel.
  std::string beam;
  std::shared_ptr<const ProjectedImage> beam_image;  // set when `beam` names an image file
  DistanceAttenuation attenuation;
  bool is_projector() const { return !slide.empty(); }
  bool has_beam_map() const { return !beam.empty(); }
};

struct Camera {
  glm::vec3 position{0.0f, 2.0f, 6.0f};  // world
  glm::vec3 target{0.0f, 1.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_degrees = 50.0f;  // vertical
  float near_plane = 0.1f;
  float far_plane = 100.0f;
};

struct Scene {
  std::vector<SceneObject> objects;
  std::vector<SpotLight> lights;
  Camera camera;
  glm::vec3 ambient{0.25f};
  glm::vec3 background{0.05f, 0.06f, 0.1f};
  int width = 640, height = 480;  // screen, pixels
};

// The mesh a caster's shadow is made from: its simplified shadow_mesh when it has one.
const Mesh &caster_mesh(const SceneObject &object);

// A sphere around a caster's shadow mesh, world space: the box's centre and the farthest vertex.
struct Sphere {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
};
Sphere caster_bounds(const SceneObject &object);

// Reads a JSON scene file (format: docs/scene_format.md). Paths inside (OBJ meshes) are relative
// to the file. False, with `error` naming the file and the field, on any problem; `scene` is
// left unchanged then.
bool load_scene(const std::string &path, Scene &scene, std::string &error);

}  // namespace gs
