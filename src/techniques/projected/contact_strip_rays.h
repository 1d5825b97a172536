// The light's rays beside a contact strip (contact_strips.h), cast on the CPU against the
// caster's triangles and the receiver's light-facing ones (world space). A strip keeps the
// caster out of texels whose receiver points should be either lit by it (the cut's visible
// side) or inside it (no camera sees them). But a receiver point outside the caster that the
// caster shadows, within a filter's reach of the strip, would read the strip's texels as light:
// beyond the line where the caster's far side meets the receiver (grazing_9507: a cylinder
// 0.42 m across through a dune under a light 0.2 m up, whose far side meets the dune within a
// texel of the cut: 0.013 -> 0.111% interior false light), past an end of the cut, or on a
// farther layer of the receiver. And a camera inside a closed caster sees the receiver's side
// inside it, in shadow, which no camera outside can (stencil17_sv1: the camera in a crate whose
// lid passes through a post; the strip lit the post under the lid, 0.262% interior false light).
// These rays find such points that the camera can see.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace gs {

struct LightView;
struct ProjectedObject;
struct SceneObject;

class ContactStripRays {
 public:
  // `caster` `closed` (step 1 culls its faces turned from the light) or open (drawn from both
  // sides: a receiver point behind any of its faces is in its shadow), `receiver` the surface
  // that masks it, `camera` the scene camera's position (world) and `camera_clip` its world to clip
  // matrix. Rays are cast only within low..high (the light's screen, texels): receiver
  // triangles whose bounds miss it are left out. `view` is kept by reference.
  ContactStripRays(const LightView &view, const SceneObject &caster, bool closed,
                   const ProjectedObject &receiver, const glm::vec3 &camera,
                   const glm::mat4 &camera_clip, const glm::vec2 &low, const glm::vec2 &high);

  // Keeps only the triangles whose bounds in the light's screen (texels) meet low..high, for
  // the rays that follow.
  void select(const glm::vec2 &low, const glm::vec2 &high);

  // Whether the light's ray through screen point p (texels) meets the receiver's mask (beyond
  // the caster's front, as step 1 draws it) after passing through the caster, on a triangle
  // facing the camera with no caster triangle facing the camera between it and the camera
  // (the scene pass culls the others): a receiver point the camera may see in the caster's
  // shadow, which no strip may light. Outside the caster, or inside it too when the camera's
  // near plane meets the closed caster's inside (kInside: only such points were found).
  enum class Seen { kNone, kOutside, kInside };
  Seen seen_in_shadow(const glm::vec2 &p) const;

 private:
  struct Face {
    glm::vec3 a, e1, e2;  // world: a corner and its two edges
    bool caster = false;
    bool light_facing = false;
    bool camera_facing = false;
    glm::vec2 low{-INFINITY}, high{INFINITY};  // the light's screen (texels); all of it when
                                               // a corner lies behind the light
    // A caster face's bounds in the camera's NDC (x, y); all of it when a corner lies behind
    // the camera: a segment from a point to the camera is one NDC point.
    glm::vec2 camera_low{-INFINITY}, camera_high{INFINITY};
  };
  struct Hit {
    float t;  // along the ray from the light, 1 at its point at NDC depth 0.5
    const Face *face;
  };
  // A triangle of vertices i, j, k of `world` (light screen `screen`, texels, valid where light
  // clip `w` > 0; camera clip `camera`); false (and nothing added) when it is a receiver
  // triangle turned from the light or whose bounds miss low..high.
  bool add(const std::vector<glm::vec3> &world, const std::vector<glm::vec2> &screen,
           const std::vector<float> &w, const std::vector<glm::vec4> &camera, const glm::uvec3 &t,
           bool caster, const glm::vec2 &low, const glm::vec2 &high);
  // The light's screen (texels) and light clip w of each of `world`'s points.
  void to_light_screen(const std::vector<glm::vec3> &world, std::vector<glm::vec2> &screen,
                       std::vector<float> &w) const;
  // Whether world point `point` lies nearer the camera than its near plane, or a caster
  // triangle facing the camera lies between it and the near plane.
  bool hidden_from_camera(const glm::vec3 &point) const;

  const LightView &view_;
  bool closed_;
  // The camera's near plane meets the inside of the closed caster (the camera inside it, or
  // the near plane cutting into it): the camera may see a receiver point inside the caster.
  bool sees_inside_ = false;
  glm::vec3 camera_;
  glm::mat4 camera_clip_, light_clip_, clip_to_world_;
  std::vector<Face> faces_;    // the caster's first, then the receiver's
  std::size_t caster_faces_ = 0;
  std::vector<const Face *> selected_;
  mutable std::vector<Hit> hits_;
};

}  // namespace gs
