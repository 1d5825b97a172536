// Stencil shadow volumes, pass by pass: ambient, the volumes (stencil_volume_geometry.cpp) counted
// into the stencil buffer, each light's lit pass, and the mask. Spaces: model and world
// (right-handed, y up); camera eye and clip through a projection whose far plane is at infinity
// (GL convention); GL window coordinates of Glide's back buffer (row 0 at the bottom; the shim
// flips rows on every read). Volumes are homogeneous world points, w = 0 away from the light.
#include "techniques/stencil_volume/stencil_volume_shadow.h"
#include "techniques/step_clock.h"

#include "techniques/plain_gl/facing_triangles.h"
#include "techniques/plain_gl/gl_api.h"
#include "techniques/plain_gl/gl_beam_mask.h"
#include "techniques/plain_gl/gl_light_units.h"
#include "scene/lighting.h"
#include "techniques/geometry/projection.h"
#include "scene/spotlight.h"
#include "techniques/stencil_volume/stencil_volume_geometry.h"

#include <glide_shim.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gs {
namespace {

using stencil_volume::build_volumes;
using stencil_volume::Caster;

// Points at infinity land at NDC depth 1 - kInfinityEpsilon instead of 1 (Kwoon, equations 3-7),
// so rounding cannot push the volumes' far ends past the far clip plane: about 8 steps of the
// 24-bit depth buffer, a negligible loss of precision.
constexpr float kInfinityEpsilon = 1.0e-6f;

using Clock = std::chrono::steady_clock;

// Kwoon's equation 7 in GL's convention (Lengyel): the camera's frustum with its far plane at
// infinity, NDC depth -1 at the near plane and 1 - kInfinityEpsilon at infinity.
glm::mat4 infinite_projection(const Camera &camera, int width, int height) {
  const float focal = 1.0f / std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  glm::mat4 p(0.0f);
  p[0][0] = focal / aspect;
  p[1][1] = focal;
  p[2][2] = kInfinityEpsilon - 1.0f;
  p[2][3] = -1.0f;
  p[3][2] = camera.near_plane * (kInfinityEpsilon - 2.0f);
  return p;
}

// One scene object as every pass draws it: the same world positions through the same matrices
// each time, so the lit pass meets the ambient pass's depth exactly (GL_EQUAL).
struct Surface {
  const SceneObject *object = nullptr;
  std::vector<glm::vec3> world, normal;  // world space, per vertex
  std::vector<glm::vec3> drawn;          // world minus FrameData::origin, what GL is given
  std::vector<glm::vec4> color;          // per vertex, rewritten by each pass
};

struct FrameData {
  // GL draws world positions relative to the camera (world - origin, exact in float for points
  // near the camera), so a scene far from the world's origin keeps its precision: a view matrix
  // with a translation of 1e6 m would round every vertex to 1/16 m.
  glm::vec3 origin{0.0f};                  // world, the camera's position
  glm::mat4 view{1.0f}, projection{1.0f};  // camera-relative world to eye, eye to clip
  std::vector<Surface> surfaces;
  std::vector<Caster> casters;
  std::vector<std::string> open_casters;  // names of casters skipped
};

void prepare_surfaces(const Scene &scene, FrameData &frame) {
  frame.origin = scene.camera.position;
  Camera at_origin = scene.camera;
  at_origin.position -= frame.origin;
  at_origin.target -= frame.origin;
  frame.view = camera_view(at_origin);
  frame.projection = infinite_projection(scene.camera, scene.width, scene.height);
  for (const SceneObject &object : scene.objects) {
    Surface surface;
    surface.object = &object;
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(object.model_to_world)));
    for (std::size_t i = 0; i < object.mesh.positions.size(); ++i) {
      surface.world.emplace_back(object.model_to_world * glm::vec4(object.mesh.positions[i], 1.0f));
      surface.drawn.push_back(surface.world.back() - frame.origin);
      surface.normal.push_back(glm::normalize(normal_matrix * object.mesh.normals[i]));
    }
    surface.color.resize(surface.world.size());
    frame.surfaces.push_back(std::move(surface));
  }
}

void prepare_casters(const Scene &scene, FrameData &frame) {
  for (const SceneObject &object : scene.objects) {
    if (!object.casts_shadow) continue;
    Caster caster;
    caster.mesh = build_edge_mesh(caster_mesh(object));
    if (!caster.mesh.closed) {
      frame.open_casters.push_back(object.name);
      continue;
    }
    for (const glm::vec3 &p : caster.mesh.positions) {
      caster.world.emplace_back(object.model_to_world * glm::vec4(p, 1.0f));
    }
    caster.inside_seen = stencil_volume::interior_may_be_seen(scene, caster_bounds(object));
    frame.casters.push_back(std::move(caster));
  }
}

// Step 2's counting into the stencil buffer (cleared first), both faces in one pass.
void count_volumes(const GlApi &gl, const std::vector<glm::vec4> &volumes, bool z_fail) {
  gl.glClear(GL_STENCIL_BUFFER_BIT);
  gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl.glDepthMask(GL_FALSE);
  // LESS, so z-fail's near cap on the caster's own dark side (same vertices, same depth) fails
  // and counts that surface in the volume: it faces away from the light, unlit either way. A
  // near cap on the lit side (a caster the camera may see inside) fails the same way and leaves
  // that surface in front of the volume, lit.
  gl.glDepthFunc(GL_LESS);
  gl.glDisable(GL_CULL_FACE);
  gl.glEnable(GL_STENCIL_TEST);
  gl.glStencilFunc(GL_ALWAYS, 0, 0xFF);
  if (z_fail) {  // Carmack's reverse: count the faces behind the visible surface
    gl.glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    gl.glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
  } else {  // count the faces in front of it
    gl.glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    gl.glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  }
  gl.glDisableClientState(GL_COLOR_ARRAY);
  gl.glVertexPointer(4, GL_FLOAT, 0, volumes.data());
  gl.glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(volumes.size()));
  gl.glEnableClientState(GL_COLOR_ARRAY);
  gl.glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gl.glEnable(GL_CULL_FACE);
  gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// The surfaces whose `receives_shadow` is `receivers`, each vertex in its `color`.
void draw_surfaces(const GlApi &gl, const std::vector<Surface> &surfaces, bool receivers) {
  for (const Surface &surface : surfaces) {
    if (surface.object->receives_shadow != receivers || surface.world.empty()) continue;
    gl.glVertexPointer(3, GL_FLOAT, 0, surface.drawn.data());
    gl.glColorPointer(4, GL_FLOAT, 0, surface.color.data());
    const std::vector<glm::uvec3> &triangles = surface.object->mesh.triangles;
    gl.glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(triangles.size() * 3), GL_UNSIGNED_INT,
                      triangles.data());
  }
}

// The state every pass starts from: the camera, depth test, back faces culled, vertex arrays.
void set_frame_state(const GlApi &gl, const FrameData &frame) {
  for (GLenum cap : {GL_DITHER, GL_LIGHTING, GL_FOG, GL_ALPHA_TEST, GL_TEXTURE_2D,
                     GL_POLYGON_OFFSET_FILL, GL_BLEND, GL_STENCIL_TEST}) {
    gl.glDisable(cap);  // dither off as in Glide's scene pass; the rest is not ours to inherit
  }
  gl.glShadeModel(GL_SMOOTH);
  gl.glDepthRange(0.0, 1.0);
  gl.glMatrixMode(GL_PROJECTION);
  gl.glLoadMatrixf(glm::value_ptr(frame.projection));
  gl.glMatrixMode(GL_MODELVIEW);
  gl.glLoadMatrixf(glm::value_ptr(frame.view));
  gl.glEnable(GL_DEPTH_TEST);
  gl.glEnable(GL_CULL_FACE);
  gl.glCullFace(GL_BACK);
  gl.glFrontFace(GL_CCW);  // CCW from outside in the world is CCW in GL's y-up window
  gl.glEnableClientState(GL_VERTEX_ARRAY);
  gl.glEnableClientState(GL_COLOR_ARRAY);
}

class StencilVolumeShadow final : public ShadowTechnique {
 public:
  explicit StencilVolumeShadow(const TechniqueOptions &options) : mode_(options.volume_mode) {}

  FrameReport render(const Scene &scene, bool synchronous) override {
    FrameReport report;
    const auto frame_start = Clock::now();
    double ms[3] = {};
    if (!begin(report.warnings)) {
      report.errors = report.warnings;  // no shadow at all
      return report;
    }
    auto start = Clock::now();
    const auto finish_step = [&](int step) {
      if (synchronous) gl_.glFinish();
      ms[step] += elapsed_ms(start);
      start = Clock::now();
    };

    FrameData frame;
    prepare_surfaces(scene, frame);  // 1
    set_frame_state(gl_, frame);
    draw_ambient_pass(scene, frame);
    finish_step(0);
    prepare_casters(scene, frame);  // 2
    for (const std::string &name : frame.open_casters) {
      // Every frame it misses a shadow (an error); the warning is given once.
      report.errors.push_back("stencil-volume: '" + name +
                              "' is not a closed mesh, so it casts no shadow volume");
      if (warned_.insert(name).second) report.warnings.push_back(report.errors.back());
    }
    finish_step(1);
    std::vector<glm::vec4> volumes;
    for (const SpotLight &light : scene.lights) {
      if (light.is_projector()) {  // slides cast no shadows: their light added unstencilled
        gl_.glDisable(GL_STENCIL_TEST);
        draw_lit_pass(light, frame);  // 3
        finish_step(2);
        continue;
      }
      const bool z_fail = uses_z_fail(scene, light);  // 2
      build_volumes(frame.casters, light.position, frame.origin, z_fail, volumes);
      count_volumes(gl_, volumes, z_fail);
      finish_step(1);
      draw_lit_pass(light, frame);  // 3
      finish_step(2);
    }
    glideShimEndGL();

    static const char *kSteps[3] = {"1 ambient pass", "2 silhouettes and volumes", "3 lit pass"};
    for (int step = 0; step < 3; ++step) report.steps.emplace_back(kSteps[step], ms[step]);
    report.total_ms = elapsed_ms(frame_start);
    return report;
  }

  void render_mask(const Scene &scene) override {
    std::vector<std::string> unused;
    if (!begin(unused)) return;
    FrameData frame;
    prepare_surfaces(scene, frame);
    prepare_casters(scene, frame);
    set_frame_state(gl_, frame);
    gl_.glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl_.glClear(GL_COLOR_BUFFER_BIT);  // colour only: depth keeps the frame's visible surfaces
    std::vector<glm::vec4> volumes;
    for (const SpotLight &light : scene.lights) {
      if (light.is_projector()) continue;  // slides cast no shadows
      const bool z_fail = uses_z_fail(scene, light);
      build_volumes(frame.casters, light.position, frame.origin, z_fail, volumes);
      count_volumes(gl_, volumes, z_fail);
      // White where the count is not 0 and this light shines on the visible surface: alpha =
      // (the surface faces the light, per face, as the truth decides it) x (the beam's
      // footprint, per pixel) at least 1/2, the one definition of shadow (technique.h).
      GlBeamMask footprint(gl_, light, 0, frame.origin);
      footprint.bind();
      gl_.glEnable(GL_ALPHA_TEST);
      gl_.glAlphaFunc(GL_GEQUAL, 0.5f);
      gl_.glDepthFunc(GL_EQUAL);
      gl_.glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
      for (const Surface &surface : frame.surfaces) {
        if (!surface.object->receives_shadow) continue;
        // Unshared corners from the same drawn positions: the depths the ambient pass wrote.
        const FacingTriangles triangles = facing_triangles(
            surface.drawn, surface.object->mesh.triangles, light.position - frame.origin);
        gl_.glVertexPointer(3, GL_FLOAT, 0, triangles.position.data());
        gl_.glColorPointer(4, GL_FLOAT, 0, triangles.color.data());
        gl_.glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles.position.size()));
      }
      gl_.glDisable(GL_ALPHA_TEST);
      footprint.release();
    }
    glideShimEndGL();
  }

 private:
  // Begins plain GL and loads its entry points (the window may be new); false with a warning.
  bool begin(std::vector<std::string> &warnings) {
    if (!glideShimBeginGL()) {
      warnings.push_back(std::string("stencil-volume: ") + glideShimGetLastErrorMessage());
      return false;
    }
    std::string error;
    if (!load_gl_api(gl_, error)) {
      glideShimEndGL();
      warnings.push_back("stencil-volume: " + error);
      return false;
    }
    return true;
  }

  bool uses_z_fail(const Scene &scene, const SpotLight &light) const {
    if (mode_ != TechniqueOptions::VolumeMode::Automatic) {
      return mode_ == TechniqueOptions::VolumeMode::ZFail;
    }
    return near_plane_may_be_in_shadow(scene, light);
  }

  // Step 1: the scene under ambient light alone, laying down the depth every later pass meets.
  void draw_ambient_pass(const Scene &scene, FrameData &frame) {
    const glm::vec3 background = glm::clamp(scene.background, 0.0f, 1.0f);
    gl_.glClearColor(background.r, background.g, background.b, 1.0f);
    gl_.glClearDepth(1.0);
    gl_.glClearStencil(0);
    gl_.glDepthMask(GL_TRUE);
    gl_.glStencilMask(0xFF);
    gl_.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl_.glDepthFunc(GL_LESS);
    Scene ambient_only;
    ambient_only.ambient = scene.ambient;
    for (Surface &surface : frame.surfaces) {
      for (std::size_t i = 0; i < surface.world.size(); ++i) {
        surface.color[i] = glm::vec4(shade_vertex(ambient_only, surface.world[i], surface.normal[i],
                                                  surface.object->mesh.colors[i]), 1.0f);
      }
    }
    draw_surfaces(gl_, frame.surfaces, true);
    draw_surfaces(gl_, frame.surfaces, false);
  }

  // Step 3: this light's direct term added where the stencil count is 0 (and, on objects that
  // receive no shadow, everywhere). Casters shadow their own far sides and whatever of
  // themselves lies in their volume, which is physically right; their lit faces lie in front of
  // their volume, which starts at the dark side (build_volumes), or on the lit faces themselves
  // for a caster the camera may see inside (count_volumes counts them behind). A caster drawn
  // from a simplified shadow_mesh is not its volume's exact surface, so a few pixels near its
  // silhouette may darken.
  // A beam map or slide, and exact attenuation, are applied per pixel by texture units 2 and 3
  // (gl_light_units.h); the vertex colours carry the rest of the light.
  void draw_lit_pass(const SpotLight &light, FrameData &frame) {
    std::optional<GlLightUnits> beam;
    float farthest = 0.0f;  // light-space depth, metres
    for (const Surface &surface : frame.surfaces)
      for (const glm::vec3 &p : surface.world) farthest = std::max(farthest, axial_distance(light, p));
    if (GlLightUnits::needed_for(light)) {
      beam.emplace(gl_, light, farthest, frame.origin);
      beam->bind();
    }
    const bool attenuation_per_pixel = beam && light.attenuation.mode == AttenuationMode::PerPixel;
    for (Surface &surface : frame.surfaces) {
      for (std::size_t i = 0; i < surface.world.size(); ++i) {
        const glm::vec3 term =
            vertex_light_term(light, surface.world[i], surface.normal[i], attenuation_per_pixel);
        surface.color[i] =
            glm::vec4(glm::min(surface.object->mesh.colors[i] * term, glm::vec3(1.0f)), 1.0f);
      }
    }
    gl_.glEnable(GL_BLEND);
    gl_.glBlendFunc(GL_ONE, GL_ONE);
    gl_.glDepthFunc(GL_EQUAL);
    gl_.glStencilFunc(GL_EQUAL, 0, 0xFF);
    draw_surfaces(gl_, frame.surfaces, true);
    gl_.glDisable(GL_STENCIL_TEST);
    draw_surfaces(gl_, frame.surfaces, false);
    gl_.glDisable(GL_BLEND);
    if (beam) beam->release();
  }

  TechniqueOptions::VolumeMode mode_;
  GlApi gl_;
  std::set<std::string> warned_;  // casters already reported as not closed
};

}  // namespace

std::unique_ptr<ShadowTechnique> make_stencil_volume_shadow(const TechniqueOptions &options) {
  return std::make_unique<StencilVolumeShadow>(options);
}

}  // namespace gs
