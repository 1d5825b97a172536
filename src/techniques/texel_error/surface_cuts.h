// The caster's cut through a receiver's surface that masks its texture (a cylinder sunk in the
// dunes: projected/pierced_receivers.h), as edges of its shadow for the edge-error estimate
// (shadow_edge_error.h). The masked texture holds that cut, and a texel beside it strays as
// any shadow edge does; step 1's contact strips (projected/contact_strips.h) keep the caster
// out of the texels beside it where no camera sees the receiver in its shadow there, and where
// a strip was dropped the texture's edge at the cut strays onto the receiver's lit side. The
// cut lies under the caster, so no true edge seen beside it excuses those pixels (issue 14:
// planar18's cylinder under the dunes, projected 0.151% interior, served with an estimate of 0).
// Spaces: world in; the light's Glide screen (texels, x right, y down) for the strips.
#pragma once

#include "techniques/geometry/projection.h"
#include "techniques/texel_error/shadow_edge_error.h"
#include "scene/scene.h"

#include <glide.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace gs {

class SurfaceCuts {
 public:
  // The caster's faces that cut, for one light: `caster` (its caster_mesh, placed by
  // model_to_world, world space) lit from `light_position` (world), and whether it is `open`
  // (step 1 draws it from both sides, so every face is lit as the light sees it: a half-buried
  // open bowl, issue 14's meshes_18307). The same for every texture of one light view (its
  // plain and masked ones), so made once and shared by them (LightView::cut_faces).
  class Faces {
   public:
    Faces(const SceneObject &caster, const glm::vec3 &light_position, bool open) {
      const Mesh &mesh = caster_mesh(caster);
      std::vector<glm::vec3> world(mesh.positions.size());
      for (std::size_t i = 0; i < world.size(); ++i) {
        world[i] = glm::vec3(caster.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
      }
      glm::vec3 low(INFINITY), high(-INFINITY);
      for (const glm::vec3 &p : world) low = glm::min(low, p), high = glm::max(high, p);
      tolerance_ = 1e-4f * glm::length(high - low);  // metres: float rounding of the caster's size
      // Only the triangles facing the light by their winding, the faces step 1 draws of a closed
      // caster; an open one's turned away too, their normal turned to the light.
      faces_.reserve(mesh.triangles.size());
      for (const glm::uvec3 &t : mesh.triangles) {
        Face face{{world[t.x], world[t.y], world[t.z]}, glm::vec3(0.0f), glm::vec3(INFINITY),
                  glm::vec3(-INFINITY)};
        face.normal = glm::cross(face.corner[1] - face.corner[0], face.corner[2] - face.corner[0]);
        if (open && glm::dot(face.normal, light_position - face.corner[0]) < 0.0f) {
          face.normal = -face.normal;
        }
        if (!(glm::dot(face.normal, light_position - face.corner[0]) > 0.0f)) continue;
        for (const glm::vec3 &c : face.corner) {
          face.low = glm::min(face.low, c), face.high = glm::max(face.high, c);
        }
        faces_.push_back(face);
      }
    }

   private:
    friend class SurfaceCuts;
    struct Face {
      glm::vec3 corner[3];
      glm::vec3 normal;  // by the winding, towards the light (not unit)
      glm::vec3 low, high;
    };
    std::vector<Face> faces_;
    float tolerance_ = 0.0f;
  };

  // The cuts of `faces` with the contact strips step 1 kept (LightView::contact_strips: each a
  // convex quad in the light's screen, texels, its corners' x and y), both held by the caller
  // while this is in use.
  SurfaceCuts(const Faces &faces, const std::vector<std::array<GrVertex, 4>> &kept_strips)
      : faces_(faces), strips_(kept_strips) {}

  // Appends to `segments` the cut of every light-facing caster triangle by the plane of the
  // convex receiver polygon `polygon` (world, unit normal `normal` towards the light) that can
  // meet it, with that triangle's normal as lit_face and a point of its part on the light's
  // side as face_point (the texture covers that side): add_shadow_edge_error clips each to the
  // polygon and, lying in its plane, takes it as a contact edge.
  void add_cuts(const std::vector<ClipVertex> &polygon, const glm::vec3 &normal,
                std::vector<SilhouetteSegment> &segments) const {
    if (polygon.size() < 3) return;
    glm::vec3 low(INFINITY), high(-INFINITY);
    for (const ClipVertex &v : polygon) {
      low = glm::min(low, v.world), high = glm::max(high, v.world);
    }
    low -= faces_.tolerance_, high += faces_.tolerance_;
    const glm::vec3 origin = polygon[0].world;
    for (const Faces::Face &face : faces_.faces_) {
      if (glm::any(glm::lessThan(face.high, low)) || glm::any(glm::greaterThan(face.low, high))) {
        continue;
      }
      float height[3];  // metres above the polygon's plane, towards the light
      for (int k = 0; k < 3; ++k) height[k] = glm::dot(normal, face.corner[k] - origin);
      if (!(std::max({height[0], height[1], height[2]}) > 0.0f) ||
          !(std::min({height[0], height[1], height[2]}) < 0.0f)) {
        continue;
      }
      glm::vec3 ends[2], above(0.0f);
      int found = 0;
      float count = 0.0f;
      for (int k = 0; k < 3; ++k) {
        const int next = (k + 1) % 3;
        if (height[k] > 0.0f) above += face.corner[k], count += 1.0f;
        if ((height[k] > 0.0f) == (height[next] > 0.0f) || found == 2) continue;
        const float f = height[k] / (height[k] - height[next]);
        ends[found++] = glm::mix(face.corner[k], face.corner[next], f);
      }
      if (found < 2) continue;
      segments.push_back({ends[0], ends[1], face.normal,
                          (above + ends[0] + ends[1]) / (count + 2.0f), false});
    }
  }

  // Whether a kept contact strip holds `texel` (the light's screen): the caster is kept out of
  // the texels there, so the texture's edge does not stray out from the cut beside it.
  bool strip_holds(const glm::vec2 &texel) const {
    for (const std::array<GrVertex, 4> &quad : strips_) {
      bool left = false, right = false;
      for (int k = 0; k < 4; ++k) {
        const GrVertex &from = quad[k], &next = quad[(k + 1) % 4];
        const glm::vec2 side = glm::vec2(next.x, next.y) - glm::vec2(from.x, from.y);
        const glm::vec2 to = texel - glm::vec2(from.x, from.y);
        const float cross = side.x * to.y - side.y * to.x;
        left = left || cross > 0.0f, right = right || cross < 0.0f;
      }
      if (!(left && right)) return true;
    }
    return false;
  }

 private:
  const Faces &faces_;
  const std::vector<std::array<GrVertex, 4>> &strips_;
};

}  // namespace gs
