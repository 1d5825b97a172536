// Stencil shadow volumes, pass by pass. Spaces: model and world (right-handed, y up); camera eye
// and clip through a projection whose far plane is at infinity (GL convention); GL window
// coordinates of Glide's back buffer (row 0 at the bottom; the shim flips rows on every read).
// Points at infinity are homogeneous world points with w = 0: a direction away from the light.
#include "techniques/stencil_volume_shadow.h"

#include "techniques/gl_api.h"
#include "techniques/gl_beam_mask.h"
#include "techniques/gl_light_units.h"
#include "scene/lighting.h"
#include "techniques/projection.h"
#include "scene/spotlight.h"

#include <glide_shim.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>

namespace gs {
namespace {

std::pair<glm::uint, glm::uint> undirected(const glm::uvec3 &edge) {
  return {std::min(edge.x, edge.y), std::max(edge.x, edge.y)};
}

// The end of the run of `edges` (sorted by undirected edge) that starts at `first`.
std::size_t end_of_edge(const std::vector<glm::uvec3> &edges, std::size_t first) {
  std::size_t end = first + 1;
  while (end < edges.size() && undirected(edges[end]) == undirected(edges[first])) ++end;
  return end;
}

// Points at infinity land at NDC depth 1 - kInfinityEpsilon instead of 1 (Kwoon, equations 3-7),
// so rounding cannot push the volumes' far ends past the far clip plane: about 8 steps of the
// 24-bit depth buffer, a negligible loss of precision.
constexpr float kInfinityEpsilon = 1.0e-6f;

using Clock = std::chrono::steady_clock;
double elapsed_ms(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}




// Whether `probe` may touch the shadow volume that `caster` casts from a point light at `light`.
// Every point of the volume lies on a ray from the light through a caster point, beyond it: in
// the cone around the sphere, no nearer the light than the sphere's nearest point.
bool may_touch_volume(const glm::vec3 &light, const Sphere &caster, const Sphere &probe) {
  const glm::vec3 to_caster = caster.centre - light, to_probe = probe.centre - light;
  const float caster_distance = glm::length(to_caster), probe_distance = glm::length(to_probe);
  if (caster_distance <= caster.radius || probe_distance <= probe.radius) return true;
  if (probe_distance + probe.radius < caster_distance - caster.radius) return false;
  const float cone = std::asin(caster.radius / caster_distance);
  const float spread = std::asin(probe.radius / probe_distance);
  const float angle = std::acos(std::clamp(
      glm::dot(to_caster, to_probe) / (caster_distance * probe_distance), -1.0f, 1.0f));
  return angle <= cone + spread + 1e-4f;  // a margin for the rounding of acos near the edge
}

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

// A closed caster, welded, in world space.
struct Caster {
  EdgeMesh mesh;
  std::vector<glm::vec3> world;  // per EdgeMesh position
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
    frame.casters.push_back(std::move(caster));
  }
}

// Every caster's shadow volume from a point light at `light`, as outward-facing triangles in
// homogeneous world coordinates relative to `origin`: the silhouette extruded to infinity and,
// for z-fail, closed by the light-facing triangles (front cap) and the back-facing ones sent to
// infinity (back cap).
void build_volumes(const std::vector<Caster> &casters, const glm::vec3 &light,
                   const glm::vec3 &origin, bool caps, std::vector<glm::vec4> &out) {
  out.clear();
  for (const Caster &caster : casters) {
    const std::vector<bool> facing = light_facing(caster.mesh, caster.world, light);
    const auto on = [&](glm::uint i) { return glm::vec4(caster.world[i] - origin, 1.0f); };
    const auto beyond = [&](glm::uint i) { return glm::vec4(caster.world[i] - light, 0.0f); };
    for (const SilhouetteEdge &e : find_silhouette(caster.mesh, facing)) {
      // The side walks the edge against the light-facing triangle, as its neighbour on the
      // volume's surface must for both to face outward.
      out.insert(out.end(), {on(e.to), on(e.from), beyond(e.from),
                             on(e.to), beyond(e.from), beyond(e.to)});
    }
    if (!caps) continue;
    for (std::size_t t = 0; t < caster.mesh.triangles.size(); ++t) {
      const glm::uvec3 &c = caster.mesh.triangles[t];
      if (facing[t]) {
        out.insert(out.end(), {on(c.x), on(c.y), on(c.z)});
      } else {
        out.insert(out.end(), {beyond(c.x), beyond(c.y), beyond(c.z)});
      }
    }
  }
}

// Step 2's counting into the stencil buffer (cleared first), both faces in one pass.
void count_volumes(const GlApi &gl, const std::vector<glm::vec4> &volumes, bool z_fail) {
  gl.glClear(GL_STENCIL_BUFFER_BIT);
  gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl.glDepthMask(GL_FALSE);
  // LESS, so a front cap on the caster's own lit face (same vertices, same depth) fails and is
  // counted with the exit behind it: the lit face stays lit.
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
      // (the surface faces the light, per vertex) x (the beam's footprint, per pixel) at least
      // 1/2, the one definition of shadow (technique.h).
      for (Surface &surface : frame.surfaces) {
        for (std::size_t i = 0; i < surface.world.size(); ++i) {
          const bool faces = glm::dot(surface.normal[i], light.position - surface.world[i]) > 0.0f;
          surface.color[i] = glm::vec4(1.0f, 1.0f, 1.0f, faces ? 1.0f : 0.0f);
        }
      }
      GlBeamMask footprint(gl_, light, 0, frame.origin);
      footprint.bind();
      gl_.glEnable(GL_ALPHA_TEST);
      gl_.glAlphaFunc(GL_GEQUAL, 0.5f);
      gl_.glDepthFunc(GL_EQUAL);
      gl_.glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
      draw_surfaces(gl_, frame.surfaces, true);
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
  // themselves lies in their volume, which is physically right; their lit faces are kept lit by
  // count_volumes' depth test. A caster drawn from a simplified shadow_mesh (the fighters) is
  // not its volume's exact surface, so a few pixels near its silhouette may darken.
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

EdgeMesh build_edge_mesh(const Mesh &mesh) {
  EdgeMesh result;
  const std::size_t n = mesh.positions.size();
  for (const glm::vec3 &p : mesh.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return result;
  }
  std::vector<glm::uint> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](glm::uint a, glm::uint b) {
    const glm::vec3 &p = mesh.positions[a], &q = mesh.positions[b];
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  });
  std::vector<glm::uint> welded(n);
  for (glm::uint i : order) {
    if (result.positions.empty() || result.positions.back() != mesh.positions[i]) {
      result.positions.push_back(mesh.positions[i]);
    }
    welded[i] = static_cast<glm::uint>(result.positions.size() - 1);
  }
  for (const glm::uvec3 &t : mesh.triangles) {
    if (t.x >= n || t.y >= n || t.z >= n) return EdgeMesh{};
    const glm::uvec3 w(welded[t.x], welded[t.y], welded[t.z]);
    // Two corners welded together: no area, and its edges (a->a, a->b, b->a) cancel out.
    if (w.x == w.y || w.y == w.z || w.z == w.x) continue;
    // Three distinct corners on one line: no area either, so it bounds nothing; its edges
    // (a->m, m->b, b->a) would otherwise make a closed surface look open.
    const glm::vec3 &a = result.positions[w.x], &b = result.positions[w.y],
                    &c = result.positions[w.z];
    if (glm::cross(b - a, c - a) == glm::vec3(0.0f)) continue;
    const auto index = static_cast<glm::uint>(result.triangles.size());
    result.triangles.push_back(w);
    for (const glm::uvec3 &edge : {glm::uvec3(w.x, w.y, index), glm::uvec3(w.y, w.z, index),
                                   glm::uvec3(w.z, w.x, index)}) {
      result.edges.push_back(edge);
    }
  }
  std::sort(result.edges.begin(), result.edges.end(),
            [](const glm::uvec3 &a, const glm::uvec3 &b) { return undirected(a) < undirected(b); });
  result.closed = true;
  for (std::size_t first = 0, end = 0; first < result.edges.size(); first = end) {
    end = end_of_edge(result.edges, first);
    int balance = 0;  // walks low -> high minus walks high -> low
    for (std::size_t k = first; k < end; ++k) {
      balance += result.edges[k].x < result.edges[k].y ? 1 : -1;
    }
    if (balance != 0) result.closed = false;
  }
  return result;
}

std::vector<bool> light_facing(const EdgeMesh &mesh, const std::vector<glm::vec3> &world,
                               const glm::vec3 &light) {
  std::vector<bool> facing(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const glm::vec3 &a = world[mesh.triangles[t].x], &b = world[mesh.triangles[t].y],
                    &c = world[mesh.triangles[t].z];
    facing[t] = glm::dot(glm::cross(b - a, c - a), light - a) > 0.0f;  // edge-on counts as away
  }
  return facing;
}

std::vector<SilhouetteEdge> find_silhouette(const EdgeMesh &mesh, const std::vector<bool> &facing) {
  std::vector<SilhouetteEdge> silhouette;
  // Per undirected edge, the light-facing walks low -> high minus those high -> low: 0 where both
  // sides face the same way; where several parts meet at one edge, each unmatched walk counts.
  for (std::size_t first = 0, end = 0; first < mesh.edges.size(); first = end) {
    end = end_of_edge(mesh.edges, first);
    const auto [low, high] = undirected(mesh.edges[first]);
    int walks = 0;
    for (std::size_t k = first; k < end; ++k) {
      if (facing[mesh.edges[k].z]) walks += mesh.edges[k].x < mesh.edges[k].y ? 1 : -1;
    }
    for (; walks > 0; --walks) silhouette.push_back({low, high});
    for (; walks < 0; ++walks) silhouette.push_back({high, low});
  }
  return silhouette;
}

bool near_plane_may_be_in_shadow(const Scene &scene, const SpotLight &light) {
  const Camera &camera = scene.camera;
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const float half_height = camera.near_plane * std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  const float half_width =
      half_height * static_cast<float>(scene.width) / static_cast<float>(scene.height);
  // A sphere around the near-plane rectangle, large enough to hold the camera position too.
  const Sphere near_plane{camera.position + forward * camera.near_plane,
                          std::sqrt(camera.near_plane * camera.near_plane +
                                    half_width * half_width + half_height * half_height)};
  for (const SceneObject &object : scene.objects) {
    if (!object.casts_shadow || caster_mesh(object).triangles.empty()) continue;
    if (may_touch_volume(light.position, caster_bounds(object), near_plane)) return true;
  }
  return false;
}

std::unique_ptr<ShadowTechnique> make_stencil_volume_shadow(const TechniqueOptions &options) {
  return std::make_unique<StencilVolumeShadow>(options);
}

}  // namespace gs
