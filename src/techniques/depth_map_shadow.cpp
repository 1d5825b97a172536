// Depth-map shadows in fixed-function GL. Spaces: world (every vertex array holds world
// positions, so all camera passes send identical vertices and meet the ambient pass's depth
// exactly); light view (the light at the origin looking down -z) and light clip (GL convention);
// light texture (s, t, r in 0..1 after the divide by q = light-view depth); camera eye and clip.
#include "techniques/depth_map_shadow.h"

#include "techniques/gl_api.h"
#include "techniques/gl_beam_mask.h"
#include "techniques/light_beam.h"
#include "techniques/gl_light_units.h"
#include "scene/lighting.h"
#include "techniques/projection.h"
#include "scene/spotlight.h"

#include <glide_shim.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace gs {
namespace {

constexpr float kWidestCone = 179.0f;  // degrees; wider, the square frustum degenerates
// Map sides refused: under 32 texels a map cannot resolve a caster (at 1 the whole cone is one
// sample), and GL's depth textures stop at 4096 here.
constexpr int kSmallestMap = 32, kLargestMap = 4096;
// The q gate: unit 1 looks up s = kGateSlope * q in a two-texel step texture (0 then 1), so a
// fragment gets the light only where q > 0.5 / kGateSlope (50 um in front of the light's
// plane). Behind the light s/q, t/q and r/q would land back in the map (back projection).
constexpr float kGateSlope = 1e4f;  // per metre of light-view depth

using Clock = std::chrono::steady_clock;
double elapsed_ms(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// An object's vertices in world space: the arrays every pass draws.
struct WorldMesh {
  const SceneObject *object = nullptr;
  std::vector<glm::vec3> position;  // world
  std::vector<glm::vec3> normal;    // world, unit
};

std::vector<WorldMesh> world_meshes(const Scene &scene) {
  std::vector<WorldMesh> meshes;
  meshes.reserve(scene.objects.size());
  for (const SceneObject &object : scene.objects) {
    WorldMesh world;
    world.object = &object;
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(object.model_to_world)));
    for (std::size_t i = 0; i < object.mesh.positions.size(); ++i) {
      world.position.push_back(
          glm::vec3(object.model_to_world * glm::vec4(object.mesh.positions[i], 1.0f)));
      world.normal.push_back(glm::normalize(normal_matrix * object.mesh.normals[i]));
    }
    meshes.push_back(std::move(world));
  }
  return meshes;
}

// A light's frustum: along the light's axis, across the part of the cone's square (the beam's
// circle inscribed) that the casters inside the beam cover, near and far fitted to the scene:
// far beyond every vertex, near before every caster's vertex in front of the light. A receiver
// nearer than that has r < 0, which compares as lit.
struct LightFrustum {
  glm::mat4 view{1.0f};        // world to light view
  glm::mat4 projection{1.0f};  // light view to light clip
  std::string problem;         // why the light has none, for the user; empty when it has one
};

LightFrustum fit_light_frustum(const std::vector<WorldMesh> &meshes, const SpotLight &light,
                               std::size_t index, int side) {
  LightFrustum frustum;
  const std::string name = "light " + std::to_string(index);
  if (!(light.cone_degrees > 0.0f && light.cone_degrees < kWidestCone)) {
    frustum.problem = name + ": a cone of " + std::to_string(light.cone_degrees) +
                      " degrees has no depth-map frustum (it must be under " +
                      std::to_string(kWidestCone) + "), so the light casts no shadow";
    return frustum;
  }
  const glm::vec3 axis = light.target - light.position;
  if (!(glm::length(axis) > 1e-6f)) {
    frustum.problem = name +
                      " has its target at its position: no depth-map frustum, so the "
                      "light casts no shadow";
    return frustum;
  }
  const glm::vec3 up =
      std::abs(glm::normalize(axis).y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  frustum.view = glm::lookAt(light.position, light.target, up);
  float farthest = 0.0f, nearest_caster = INFINITY;  // light-view depth, metres
  for (const WorldMesh &mesh : meshes) {
    for (const glm::vec3 &p : mesh.position) {
      const float depth = -(frustum.view * glm::vec4(p, 1.0f)).z;
      farthest = std::max(farthest, depth);
      if (mesh.object->casts_shadow) nearest_caster = std::min(nearest_caster, depth);
    }
  }
  // A 1000:1 range at the most: 24 bits then still resolve about a millimetre at 10 m. (With
  // no caster the map stays empty and any near plane will do.)
  const float far_plane = std::max(farthest, 1e-3f) * 1.01f;
  const float near_plane = std::clamp(nearest_caster * 0.99f, far_plane * 1e-3f, far_plane * 0.5f);
  // The map holds only what can shadow a point the light shines on: the casters clipped to the
  // beam (light_beam.h), seen along the light's own axis (so q is the light's depth, and the q
  // gate and the beam stay where they are). Their box of directions, plus two texels for the
  // percentage-closer lookup's reach, is usually far narrower than the cone, and every texel
  // finer; a receiver outside it lies on no ray through a caster, and the lit border says so.
  const float t = std::tan(glm::radians(light.cone_degrees) * 0.5f);
  glm::vec2 low(-t), high(t);  // tangents x / -z, y / -z
  const LightBeam beam = light_beam(light);
  glm::vec2 box_low(INFINITY), box_high(-INFINITY);
  for (const WorldMesh &mesh : meshes) {
    if (!mesh.object->casts_shadow) continue;
    bool whole = false;
    for (const glm::vec3 &p : clip_to_beam(mesh.position, mesh.object->mesh.triangles, beam,
                                           far_plane * 1e-4f, whole)) {
      const glm::vec3 v = glm::vec3(frustum.view * glm::vec4(p, 1.0f));
      if (!(-v.z > 0.0f)) continue;
      const glm::vec2 tangent = glm::vec2(v.x, v.y) / -v.z;
      box_low = glm::min(box_low, tangent);
      box_high = glm::max(box_high, tangent);
    }
  }
  if (box_low.x <= box_high.x && box_low.y <= box_high.y) {
    const glm::vec2 width = glm::max(box_high - box_low, glm::vec2(t * 1e-4f));
    const glm::vec2 pad =
        width * (2.0f / std::max(static_cast<float>(side) - 4.0f, 1.0f)) + glm::vec2(t * 1e-6f);
    low = glm::max(box_low - pad, low);
    high = glm::min(box_high + pad, high);
  }
  frustum.projection = glm::frustum(low.x * near_plane, high.x * near_plane, low.y * near_plane,
                                    high.y * near_plane, near_plane, far_plane);
  return frustum;
}

// Whether a vertex's surface faces `light`: where the mask may say the depth map took it away
// (whether the point is in the light's beam is decided per pixel, by GlBeamMask).
bool faces(const SpotLight &light, const glm::vec3 &world, const glm::vec3 &normal) {
  return glm::dot(normal, light.position - world) > 0.0f;
}

// The GL objects and passes of one frame. Textures and framebuffer are made and deleted with
// it, inside one glideShimBeginGL .. glideShimEndGL, so none outlives the window it was made in.
class Passes {
 public:
  Passes(const GlApi &gl, const Scene &scene, const TechniqueOptions &options);
  ~Passes();
  Passes(const Passes &) = delete;
  Passes &operator=(const Passes &) = delete;

  // Step 1; a light left without its map is an error (it casts no shadow).
  void depth_from_lights(std::vector<std::string> &warnings, std::vector<std::string> &errors);
  void ambient_pass();                                         // step 2
  void lit_passes();                                           // step 3
  // The mask over the frame's depth buffer (after steps 1-3 of the same scene).
  void mask_passes();

 private:
  void use_camera();
  // Unit 0: light `light`'s map compared with `compare` (LEQUAL: 1 where lit); unit 1: the q
  // gate. Texgen planes are given while the modelview is the camera's view, so they act on
  // world coordinates (Everitt et al., Appendix A).
  void bind_shadow_units(std::size_t light, GLenum compare);
  void release_shadow_units();
  void draw(const WorldMesh &mesh, const std::vector<glm::vec4> &colors);
  float farthest_from(const SpotLight &light) const;  // largest light-space depth, metres

  const GlApi &gl_;
  const Scene &scene_;
  const TechniqueOptions &options_;
  std::vector<WorldMesh> meshes_;
  std::vector<LightFrustum> frustums_;  // per light
  std::vector<GLuint> maps_;            // per light; 0: the light casts no shadow
  GLuint framebuffer_ = 0;              // step 1's, depth only
  GLuint gate_ = 0;                     // the q gate's step texture
  GLint target_framebuffer_ = 0;        // the shim's, holding Glide's back buffer
  GLint window_[4] = {};                // the shim's viewport: the whole window
};

Passes::Passes(const GlApi &gl, const Scene &scene, const TechniqueOptions &options)
    : gl_(gl), scene_(scene), options_(options), meshes_(world_meshes(scene)) {
  gl_.glGetIntegerv(GL_FRAMEBUFFER_BINDING, &target_framebuffer_);
  gl_.glGetIntegerv(GL_VIEWPORT, window_);
  gl_.glDisable(GL_DITHER);  // exact 565 levels, as Glide draws with dithering off
  gl_.glEnableClientState(GL_VERTEX_ARRAY);
  const GLubyte step[2] = {0, 255};
  gl_.glGenTextures(1, &gate_);
  gl_.glBindTexture(GL_TEXTURE_2D, gate_);
  gl_.glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 2, 1, 0, GL_ALPHA, GL_UNSIGNED_BYTE, step);
  gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl_.glBindTexture(GL_TEXTURE_2D, 0);
}

Passes::~Passes() {
  for (GLuint map : maps_) {
    if (map != 0) gl_.glDeleteTextures(1, &map);
  }
  gl_.glDeleteTextures(1, &gate_);
  if (framebuffer_ != 0) gl_.glDeleteFramebuffers(1, &framebuffer_);
}

void Passes::depth_from_lights(std::vector<std::string> &warnings,
                               std::vector<std::string> &errors) {
  gl_.glGenFramebuffers(1, &framebuffer_);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.glDrawBuffer(GL_NONE);
  gl_.glReadBuffer(GL_NONE);
  gl_.glEnable(GL_DEPTH_TEST);
  gl_.glDepthFunc(GL_LESS);
  gl_.glDepthMask(GL_TRUE);
  gl_.glDisable(GL_CULL_FACE);  // a caster shadows from whichever side the light sees it
  // Pushed away from the light by the slope (light-view depth per texel) and a few depth units,
  // so a lit surface compares nearer than its own sample (Everitt et al., "Why is polygon
  // offset needed?").
  gl_.glEnable(GL_POLYGON_OFFSET_FILL);
  gl_.glPolygonOffset(options_.depth_bias_slope, options_.depth_bias_units);
  const GLint filter = options_.depth_map_linear ? GL_LINEAR : GL_NEAREST;
  const GLfloat lit_border[4] = {1.0f, 1.0f, 1.0f, 1.0f};  // depth 1: outside the map is lit
  if (options_.depth_map_bits != 16 && options_.depth_map_bits != 24) {
    warnings.push_back("depth-map: " + std::to_string(options_.depth_map_bits) +
                       "-bit depth maps do not exist (16 or 24); using 24");
  }
  for (std::size_t light = 0; light < scene_.lights.size(); ++light) {
    maps_.push_back(0);
    if (scene_.lights[light].is_projector()) {  // slides cast no shadows: no map, gate open
      frustums_.emplace_back();
      continue;
    }
    const GLsizei side =
        options_.projected.size > 0 ? options_.projected.size : scene_.lights[light].shadow_size;
    frustums_.push_back(fit_light_frustum(meshes_, scene_.lights[light], light, side));
    const LightFrustum &frustum = frustums_.back();
    if (side < kSmallestMap || side > kLargestMap) {
      errors.push_back("depth-map: a map of " + std::to_string(side) + " texels for light " +
                       std::to_string(light) + " is outside " + std::to_string(kSmallestMap) +
                       ".." + std::to_string(kLargestMap) + ", so the light casts no shadow");
      warnings.push_back(errors.back());
      maps_.back() = 0;
      continue;
    }
    if (!frustum.problem.empty()) {
      warnings.push_back(frustum.problem);
      errors.push_back(frustum.problem);
      continue;
    }
    GLuint map = 0;
    gl_.glGenTextures(1, &map);
    gl_.glBindTexture(GL_TEXTURE_2D, map);
    const GLint format =
        options_.depth_map_bits == 16 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24;
    gl_.glTexImage2D(GL_TEXTURE_2D, 0, format, side, side, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                     nullptr);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    gl_.glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, lit_border);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);  // (0, 0, 0, result)
    gl_.glBindTexture(GL_TEXTURE_2D, 0);
    gl_.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map, 0);
    if (gl_.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      const std::string size = std::to_string(side);
      errors.push_back("light " + std::to_string(light) + ": a " + size + "x" + size +
                       " depth texture cannot be rendered to, so the light casts no shadow");
      warnings.push_back(errors.back());
      gl_.glDeleteTextures(1, &map);
      continue;
    }
    maps_.back() = map;
    gl_.glViewport(0, 0, side, side);
    gl_.glClearDepth(1.0);  // the light's far plane (Glide's own clears leave other values)
    gl_.glClear(GL_DEPTH_BUFFER_BIT);
    gl_.glMatrixMode(GL_PROJECTION);
    gl_.glLoadMatrixf(&frustum.projection[0][0]);
    gl_.glMatrixMode(GL_MODELVIEW);
    gl_.glLoadMatrixf(&frustum.view[0][0]);
    // Full meshes, not shadow_mesh: a simplified caster would shadow the surface it cuts into.
    for (const WorldMesh &mesh : meshes_) {
      if (!mesh.object->casts_shadow) continue;
      gl_.glVertexPointer(3, GL_FLOAT, 0, mesh.position.data());
      gl_.glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.object->mesh.triangles.size() * 3),
                         GL_UNSIGNED_INT, mesh.object->mesh.triangles.data());
    }
  }
  gl_.glDisable(GL_POLYGON_OFFSET_FILL);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target_framebuffer_));
}

void Passes::use_camera() {
  // GL rows run from the bottom: the scene's screen is the window's top-left part, as in Glide.
  gl_.glViewport(window_[0], window_[1] + window_[3] - scene_.height, scene_.width, scene_.height);
  const glm::mat4 projection = camera_projection(scene_.camera, scene_.width, scene_.height);
  const glm::mat4 view = camera_view(scene_.camera);
  gl_.glMatrixMode(GL_PROJECTION);
  gl_.glLoadMatrixf(&projection[0][0]);
  gl_.glMatrixMode(GL_MODELVIEW);
  gl_.glLoadMatrixf(&view[0][0]);
  gl_.glEnable(GL_DEPTH_TEST);
  gl_.glEnable(GL_CULL_FACE);  // counter-clockwise from outside, as the scene pass culls
  gl_.glFrontFace(GL_CCW);
  gl_.glCullFace(GL_BACK);
  gl_.glEnableClientState(GL_COLOR_ARRAY);
}

void Passes::ambient_pass() {
  use_camera();
  // The background as Glide's clear writes it: 8 bits per channel truncated to 565.
  const glm::ivec3 background(glm::clamp(scene_.background, 0.0f, 1.0f) * 255.0f);
  gl_.glClearColor(static_cast<float>(background.r >> 3) / 31.0f,
                   static_cast<float>(background.g >> 2) / 63.0f,
                   static_cast<float>(background.b >> 3) / 31.0f, 1.0f);
  gl_.glClearDepth(1.0);
  gl_.glDepthMask(GL_TRUE);
  gl_.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl_.glDepthFunc(GL_LEQUAL);
  Scene ambient_only;  // shade_vertex with the lights removed: ambient x albedo
  ambient_only.ambient = scene_.ambient;
  for (const WorldMesh &mesh : meshes_) {
    std::vector<glm::vec4> colors;
    for (std::size_t i = 0; i < mesh.position.size(); ++i) {
      colors.emplace_back(
          shade_vertex(ambient_only, mesh.position[i], mesh.normal[i], mesh.object->mesh.colors[i]),
          1.0f);
    }
    draw(mesh, colors);
  }
}

void Passes::lit_passes() {
  use_camera();
  gl_.glDepthFunc(GL_EQUAL);  // only the visible surface, drawn from the same vertices
  gl_.glDepthMask(GL_FALSE);
  gl_.glEnable(GL_BLEND);
  gl_.glBlendFunc(GL_SRC_ALPHA, GL_ONE);  // adds the light x the lit fraction of the 2x2
  for (std::size_t light = 0; light < scene_.lights.size(); ++light) {
    const SpotLight &spot = scene_.lights[light];
    bind_shadow_units(light, GL_LEQUAL);
    // A beam map or slide, and exact attenuation, are applied per pixel by units 2 and 3; the
    // vertex colours carry the rest of the light.
    std::optional<GlLightUnits> beam;
    if (GlLightUnits::needed_for(spot)) {
      beam.emplace(gl_, spot, farthest_from(spot));
      beam->bind();
    }
    const bool attenuation_per_pixel =
        beam && spot.attenuation.mode == AttenuationMode::PerPixel;
    for (const WorldMesh &mesh : meshes_) {
      std::vector<glm::vec4> colors;
      for (std::size_t i = 0; i < mesh.position.size(); ++i) {
        const glm::vec3 light_term =
            vertex_light_term(spot, mesh.position[i], mesh.normal[i], attenuation_per_pixel);
        colors.emplace_back(glm::min(mesh.object->mesh.colors[i] * light_term, glm::vec3(1.0f)),
                            1.0f);
      }
      gl_.glActiveTexture(GL_TEXTURE0);
      if (maps_[light] != 0 && mesh.object->receives_shadow) {
        gl_.glEnable(GL_TEXTURE_2D);
      } else {
        gl_.glDisable(GL_TEXTURE_2D);
      }
      draw(mesh, colors);
    }
    if (beam) beam->release();
  }
  release_shadow_units();
  gl_.glDisable(GL_BLEND);
}

float Passes::farthest_from(const SpotLight &light) const {
  float farthest = 0.0f;
  for (const WorldMesh &mesh : meshes_)
    for (const glm::vec3 &p : mesh.position) farthest = std::max(farthest, axial_distance(light, p));
  return farthest;
}

void Passes::mask_passes() {
  use_camera();
  gl_.glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  gl_.glClear(GL_COLOR_BUFFER_BIT);  // colour only: the depth buffer keeps the frame's surfaces
  gl_.glDepthFunc(GL_EQUAL);
  gl_.glDepthMask(GL_FALSE);
  // White where alpha = (the surface faces the light, per vertex) x (the shadowed fraction of the
  // percentage-closer lookup) x (q gate) x (the beam's footprint, per pixel) is at least 1/2:
  // the one definition of shadow (technique.h), at least half of the light's view blocked where
  // the light shines.
  gl_.glEnable(GL_ALPHA_TEST);
  gl_.glAlphaFunc(GL_GEQUAL, 0.5f);
  for (std::size_t light = 0; light < scene_.lights.size(); ++light) {
    if (scene_.lights[light].is_projector()) continue;
    if (maps_[light] == 0) continue;
    const SpotLight &spot = scene_.lights[light];
    GlBeamMask footprint(gl_, spot, 2);
    bind_shadow_units(light, GL_GREATER);  // the comparison inverted: 1 where in shadow
    footprint.bind();
    gl_.glActiveTexture(GL_TEXTURE0);
    gl_.glEnable(GL_TEXTURE_2D);
    for (const WorldMesh &mesh : meshes_) {
      if (!mesh.object->receives_shadow) continue;
      std::vector<glm::vec4> colors;
      for (std::size_t i = 0; i < mesh.position.size(); ++i) {
        colors.emplace_back(1.0f, 1.0f, 1.0f,
                            faces(spot, mesh.position[i], mesh.normal[i]) ? 1.0f : 0.0f);
      }
      draw(mesh, colors);
    }
    footprint.release();
  }
  release_shadow_units();
  gl_.glDisable(GL_ALPHA_TEST);
}

void Passes::bind_shadow_units(std::size_t light, GLenum compare) {
  // A light without a frustum keeps identity matrices: q = 1 everywhere, the gate open, and
  // unit 0 is left disabled, so it lights without shadows.
  const LightFrustum &frustum = frustums_[light];
  const glm::mat4 light_clip = frustum.projection * frustum.view;  // world to light clip
  // (q, its w, is the light-view depth along the light's own axis, as the gate needs.)
  // S: light clip to texture coordinates, s, t, r = 0.5 (x, y, z) + 0.5 w, q = w.
  const glm::mat4 bias = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  const glm::mat4 to_map = bias * light_clip;
  glm::mat4 to_gate(0.0f);  // s = kGateSlope q, t = 0, q = 1
  to_gate[0][0] = kGateSlope * light_clip[0][3];
  to_gate[1][0] = kGateSlope * light_clip[1][3];
  to_gate[2][0] = kGateSlope * light_clip[2][3];
  to_gate[3][0] = kGateSlope * light_clip[3][3];
  to_gate[3][3] = 1.0f;
  const GLuint textures[2] = {maps_[light], gate_};
  const glm::mat4 *planes[2] = {&to_map, &to_gate};
  for (int unit = 0; unit < 2; ++unit) {
    gl_.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    gl_.glBindTexture(GL_TEXTURE_2D, textures[unit]);
    gl_.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);  // alpha x= texture alpha
    const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
    const GLenum enables[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                               GL_TEXTURE_GEN_Q};
    for (int row = 0; row < 4; ++row) {
      const glm::mat4 &m = *planes[unit];
      const GLfloat plane[4] = {m[0][row], m[1][row], m[2][row], m[3][row]};
      gl_.glTexGeni(coords[row], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
      gl_.glTexGenfv(coords[row], GL_EYE_PLANE, plane);
      gl_.glEnable(enables[row]);
    }
  }
  gl_.glEnable(GL_TEXTURE_2D);  // unit 1, the gate; unit 0 per object
  if (maps_[light] != 0) {
    gl_.glActiveTexture(GL_TEXTURE0);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(compare));
  }
}

void Passes::release_shadow_units() {
  for (int unit = 1; unit >= 0; --unit) {
    gl_.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    gl_.glBindTexture(GL_TEXTURE_2D, 0);
    gl_.glDisable(GL_TEXTURE_2D);
    for (GLenum gen : {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q}) {
      gl_.glDisable(gen);
    }
  }
}

void Passes::draw(const WorldMesh &mesh, const std::vector<glm::vec4> &colors) {
  gl_.glVertexPointer(3, GL_FLOAT, 0, mesh.position.data());
  gl_.glColorPointer(4, GL_FLOAT, 0, colors.data());
  gl_.glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.object->mesh.triangles.size() * 3),
                     GL_UNSIGNED_INT, mesh.object->mesh.triangles.data());
}

// GL errors the passes raised, as one warning each (they mean a bug here, not a user error).
void report_gl_errors(const GlApi &gl, std::vector<std::string> &warnings) {
  for (GLenum error = gl.glGetError(); error != GL_NO_ERROR; error = gl.glGetError()) {
    char text[64];
    std::snprintf(text, sizeof text, "depth-map: GL error 0x%04X", error);
    warnings.emplace_back(text);
  }
}

class DepthMapShadow final : public ShadowTechnique {
 public:
  explicit DepthMapShadow(const TechniqueOptions &options) : options_(options) {}

  FrameReport render(const Scene &scene, bool synchronous) override {
    FrameReport report;
    const auto frame_start = Clock::now();
    GlApi gl;
    if (!begin(gl, report.warnings)) {
      report.errors = report.warnings;  // no shadow at all
      return report;
    }
    {
      Passes passes(gl, scene, options_);
      auto step = [&](const char *name, auto &&pass) {
        const auto start = Clock::now();
        pass();
        if (synchronous) gl.glFinish();
        report.steps.emplace_back(name, elapsed_ms(start));
      };
      step("1 depth from the light",
           [&] { passes.depth_from_lights(report.warnings, report.errors); });
      step("2 ambient pass", [&] { passes.ambient_pass(); });
      step("3 lit pass with the depth test", [&] { passes.lit_passes(); });
    }
    report_gl_errors(gl, report.warnings);
    glideShimEndGL();
    report.total_ms = elapsed_ms(frame_start);
    return report;
  }

  void render_mask(const Scene &scene) override {
    GlApi gl;
    std::vector<std::string> ignored;  // render reported them for this scene
    if (!begin(gl, ignored)) return;
    {
      // The maps are made again rather than kept from render: no GL object outlives a call.
      Passes passes(gl, scene, options_);
      passes.depth_from_lights(ignored, ignored);
      passes.mask_passes();
    }
    glideShimEndGL();
  }

 private:
  static bool begin(GlApi &gl, std::vector<std::string> &warnings) {
    if (!glideShimBeginGL()) {
      warnings.push_back(std::string("depth-map: no plain GL: ") + glideShimGetLastErrorMessage());
      return false;
    }
    std::string error;
    if (!load_gl_api(gl, error)) {
      warnings.push_back("depth-map: " + error);
      glideShimEndGL();
      return false;
    }
    return true;
  }

  TechniqueOptions options_;
};

}  // namespace

std::unique_ptr<ShadowTechnique> make_depth_map_shadow(const TechniqueOptions &options) {
  return std::make_unique<DepthMapShadow>(options);
}

}  // namespace gs
