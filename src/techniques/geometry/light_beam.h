// Where a spotlight shines, as the techniques that work with geometry need it: pyramids of planes
// through the light's position. A world point p is inside a plane when dot(plane, (p, 1)) >= 0.
//   inner  a pyramid inside the beam: the techniques clip their shadows to it, so no shadow falls
//          where the light does not shine (the ground truth calls a point outside the beam
//          `Outside`, and a shadow there is false);
//   outer  a pyramid holding the whole beam: a caster's part outside it can only shadow points
//          outside the beam, so the projected technique fits its light view to the part inside.
// The round beam (a light without a beam map, and the round, gobo and lens maps, which are 0
// outside the unit circle of the beam plane) is the cone: `kConeSides` planes inscribed in it and
// as many tangent to it, which differ from the cone by 1 - cos(pi / 64), 0.12% of its radius.
// A square beam, or an image, fills the beam plane's square: the same four planes inside and out.
// Inside the footprint an image's dark parts are not excluded (a gobo's bars are: `regions`).
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace gs {

constexpr int kConeSides = 64;

struct LightBeam {
  std::vector<glm::vec4> inner, outer;  // world planes through the light
  // Convex pieces of `inner` whose union is where the beam is lit: `inner` itself, or for the
  // gobo its four panes (the bars, |u| or |v| under 0.05 on the beam plane, are planes through
  // the light too). Shadows are clipped to each piece.
  std::vector<std::vector<glm::vec4>> regions;
  glm::vec3 position{0.0f}, axis{0.0f, 0.0f, -1.0f};  // world; axis unit
  // A point at least this cosine from the axis lies inside `inner` (the cone inscribed in the
  // inner pyramid); -2 for a square beam, where only the planes tell.
  float inner_cosine = -2.0f;
  // The index in `regions` of the piece that surely holds `world` (the pieces are disjoint),
  // or -1 when none surely does: a quick test, so -1 may still be inside.
  int region_holding(const glm::vec3 &world) const;
  // Whether the triangle a, b, c (world) lies wholly in one lit piece: its three corners in the
  // same one (each piece is convex). Corners in different panes of a gobo say nothing of the
  // bar between them.
  bool surely_holds_triangle(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c) const;
};

LightBeam light_beam(const SpotLight &light);

// Whether `world` lies inside every plane of `planes`.
bool inside_planes(const std::vector<glm::vec4> &planes, const glm::vec3 &world);

// The triangles of a mesh (world positions) clipped to the beam's outer pyramid and to a plane
// `margin` in front of the light, as the corners of the pieces left: every point of the mesh
// that can stand between the light and something it shines on. `whole` says whether nothing
// was cut off (then the corners are `world` itself).
std::vector<glm::vec3> clip_to_beam(const std::vector<glm::vec3> &world,
                                    const std::vector<glm::uvec3> &triangles,
                                    const LightBeam &beam, float margin, bool &whole);

}  // namespace gs
