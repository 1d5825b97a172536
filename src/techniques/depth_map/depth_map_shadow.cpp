// Depth-map shadows, steps 2 and 3 and the mask: the camera's passes over the maps that
// depth_map_from_light.cpp made, and the technique itself. Spaces: world, of the scene moved to
// its local origin (local_origin.h) so that no pass loses precision far from the world's origin
// (every vertex array holds those positions, so all camera passes send identical vertices and
// meet the ambient pass's depth exactly); light clip (GL convention) and light texture (s, t, r
// in 0..1 after the divide by q = light-view depth) in the texgen planes; camera eye and clip.
#include "techniques/depth_map/depth_map_shadow.h"
#include "techniques/step_clock.h"

#include "techniques/depth_map/depth_map_lookup.h"
#include "techniques/depth_map/depth_map_passes.h"
#include "techniques/plain_gl/facing_triangles.h"
#include "techniques/plain_gl/gl_api.h"
#include "techniques/plain_gl/gl_beam_mask.h"
#include "techniques/plain_gl/gl_light_units.h"
#include "scene/lighting.h"
#include "scene/local_origin.h"
#include "techniques/geometry/projection.h"
#include "scene/spotlight.h"

#include <glide_shim.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace gs {
namespace depth_map {
namespace {

// The q gate: unit 1 looks up s = kGateSlope * q in a two-texel step texture (0 then 1), so a
// fragment gets the light only where q > 0.5 / kGateSlope (50 um in front of the light's
// plane). Behind the light s/q, t/q and r/q would land back in the map (back projection).
constexpr float kGateSlope = 1e4f;  // per metre of light-view depth

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
    if (object.casts_shadow) {
      world.surface = build_edge_mesh(object.mesh);
      for (const glm::vec3 &p : world.surface.positions) {
        world.surface_world.push_back(glm::vec3(object.model_to_world * glm::vec4(p, 1.0f)));
      }
    }
    meshes.push_back(std::move(world));
  }
  return meshes;
}

}  // namespace

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
        // Unshared corners from the same world positions (the depths the ambient pass wrote),
        // each triangle with its own lowered depth.
        std::vector<glm::vec3> corners;
        std::vector<glm::vec4> corner_colors;
        for (const glm::uvec3 &triangle : mesh.object->mesh.triangles) {
          for (int k = 0; k < 3; ++k) {
            corners.push_back(mesh.position[triangle[k]]);
            corner_colors.push_back(colors[triangle[k]]);
          }
        }
        draw_receiver(corners, corner_colors, mesh.object->casts_shadow);
      } else {
        gl_.glDisable(GL_TEXTURE_2D);
        draw(mesh, colors);
      }
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
  // White where alpha = (the surface faces the light, per face) x (the shadowed fraction of the
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
      // Unshared corners from the same world positions: the depths the ambient pass wrote.
      const FacingTriangles triangles =
          facing_triangles(mesh.position, mesh.object->mesh.triangles, spot.position);
      draw_receiver(triangles.position, triangles.color, mesh.object->casts_shadow);
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
  to_map_ = texture_from_clip() * light_clip;
  bound_side_ = sides_[light];
  glm::mat4 to_gate(0.0f);  // s = kGateSlope q, t = 0, q = 1
  to_gate[0][0] = kGateSlope * light_clip[0][3];
  to_gate[1][0] = kGateSlope * light_clip[1][3];
  to_gate[2][0] = kGateSlope * light_clip[2][3];
  to_gate[3][0] = kGateSlope * light_clip[3][3];
  to_gate[3][3] = 1.0f;
  const GLuint textures[2] = {maps_[light], gate_};
  for (int unit = 0; unit < 2; ++unit) {
    gl_.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    gl_.glBindTexture(GL_TEXTURE_2D, textures[unit]);
    gl_.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);  // alpha x= texture alpha
  }
  // Unit 1 (active): the gate's coordinates by texgen; unit 0's come per corner (draw_receiver).
  const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  const GLenum enables[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                             GL_TEXTURE_GEN_Q};
  for (int row = 0; row < 4; ++row) {
    const GLfloat plane[4] = {to_gate[0][row], to_gate[1][row], to_gate[2][row], to_gate[3][row]};
    gl_.glTexGeni(coords[row], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    gl_.glTexGenfv(coords[row], GL_EYE_PLANE, plane);
    gl_.glEnable(enables[row]);
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

void Passes::draw_receiver(const std::vector<glm::vec3> &corners,
                           const std::vector<glm::vec4> &colors, bool casts) {
  const std::vector<glm::vec4> coords =
      biased_map_coords(corners, to_map_, bound_side_, casts ? options_.depth_bias_receiver : 0.0f);
  gl_.glEnableClientState(GL_TEXTURE_COORD_ARRAY);  // client unit 0, the map's
  gl_.glTexCoordPointer(4, GL_FLOAT, 0, coords.data());
  gl_.glVertexPointer(3, GL_FLOAT, 0, corners.data());
  gl_.glColorPointer(4, GL_FLOAT, 0, colors.data());
  gl_.glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners.size()));
  gl_.glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}

void Passes::draw(const WorldMesh &mesh, const std::vector<glm::vec4> &colors) {
  gl_.glVertexPointer(3, GL_FLOAT, 0, mesh.position.data());
  gl_.glColorPointer(4, GL_FLOAT, 0, colors.data());
  gl_.glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.object->mesh.triangles.size() * 3),
                     GL_UNSIGNED_INT, mesh.object->mesh.triangles.data());
}

}  // namespace depth_map

namespace {

using Clock = std::chrono::steady_clock;

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
      // Every pass in local coordinates (local_origin.h): the map's depths and the lookup's r
      // are then as precise wherever the scene stands.
      Scene moved;
      depth_map::Passes passes(gl, in_local_coordinates(scene, moved), options_);
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
      report.texel_footprint_px = passes.texel_footprint_px();
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
      Scene moved;  // the frame's depths in local coordinates, as render drew them
      depth_map::Passes passes(gl, in_local_coordinates(scene, moved), options_);
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
