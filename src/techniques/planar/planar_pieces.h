// Internal to the planar technique's step 1 (planar_casting.cpp, planar_hidden.cpp): the caster
// and receiver triangles it pairs, the small polygons it clips, and the regions of a receiver's
// plane a caster hides from the camera. Spaces: world (all geometry); light directions (light
// view x/-z, y/-z: where the light sees a point, used only to reject pairs early).
#pragma once

#include "techniques/geometry/light_beam.h"

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gs::planar {

// A caster point this close to the light's height above a receiver plane (as a fraction of that
// height) would project over a thousand times farther than it is from the light: such parts are
// cut off (top_of_casting says when that loses nothing), since float precision would not reach.
// The camera's height above a plane bounds the hidden regions the same way.
constexpr float kNearLightHeight = 0.999f;

// Light directions of a triangle: the rectangle around its corners' (x/-z, y/-z) in light view.
// A triangle reaching behind the light's view plane has no such rectangle and gets all of
// direction space.
struct DirectionBox {
  glm::vec2 low{-INFINITY}, high{INFINITY};
  bool overlaps(const DirectionBox &other) const {
    return low.x <= other.high.x && other.low.x <= high.x && low.y <= other.high.y &&
           other.low.y <= high.y;
  }
  void include(const DirectionBox &other) {
    low = glm::min(low, other.low);
    high = glm::max(high, other.high);
  }
};

constexpr DirectionBox kEmptyBox{glm::vec2(INFINITY), glm::vec2(-INFINITY)};

struct CasterTriangle {
  std::array<glm::vec3, 3> corner;  // world, counter-clockwise seen from the light
  DirectionBox box;
  float light_distance = 0.0f;      // metres from the light to the triangle's nearest point
};

struct PlanarCaster {
  std::size_t object = 0;  // index into scene.objects
  std::vector<CasterTriangle> triangles;
  DirectionBox box = kEmptyBox;
  // The triangles of its drawn mesh (not shadow_mesh) facing the camera, as the scene pass draws
  // them (corners counter-clockwise seen from the camera): the surfaces that may hide a
  // receiver's plane where they pass through it (HiddenRegion).
  std::vector<CasterTriangle> seen;
};

// A receiver triangle facing the light, with its plane and edges ready for clipping.
struct ReceiverTriangle {
  std::uint32_t index = 0;          // into the object's mesh.triangles
  std::array<glm::vec3, 3> corner;  // world, counter-clockwise seen from the light
  glm::vec3 normal{0.0f};           // world, unit, on the light's side
  float offset = 0.0f;              // dot(normal, p) of the plane's points
  float light_height = 0.0f;        // the light's distance above the plane, metres (> 0)
  // The same plane in double, for the projection from the light (planar_casting.cpp's cast_on):
  // a plane passing 0.14 mm from a light 4.7 m away (/work/aud17 near_17030: a fighter's
  // triangle edge-on to the light) left the float height below the cut, 0.999 of the light's,
  // level with the light, and the projection made a NaN vertex.
  glm::dvec3 exact_normal{0.0};     // world, unit, on the light's side
  double exact_offset = 0.0;        // dot(exact_normal, p) of the plane's points
  double exact_light_height = 0.0;  // metres (> 0)
  float light_reach = 0.0f;         // metres from the light to the farthest corner
  std::array<glm::vec3, 3> inward;  // world, in the plane: into the triangle from edge i, i+1
  // dot(inward[i], p) >= inward_offset[i] inside edge i moved out by the triangle's snap slack
  // (what a sixteenth of a pixel spans on it: planar_casting.cpp's prepare_receiver).
  std::array<float, 3> inward_offset{};
  DirectionBox box;
  bool beyond_beam = false;         // not wholly inside the light's inner beam: clip to it
};

// A convex polygon during clipping: a triangle cut by five planes has at most eight corners, and
// the beam region's planes (at most kConeSides and a gobo's two bars) add one each.
struct SmallPolygon {
  std::array<glm::vec3, 10 + kConeSides> v;
  std::size_t n = 0;
};

// Sutherland-Hodgman against one plane: keeps the part where dot(normal, p) >= offset.
void clip_keep(SmallPolygon &polygon, const glm::vec3 &normal, float offset, SmallPolygon &scratch);

// Where a caster's drawn triangle passes through a receiver triangle's plane, its part on the
// light's side of the plane hides from the camera a region of the plane that starts at their
// common line. The caster's shadow on the plane starts at that line too, and there the shadow
// polygon lies within a depth margin (planar_shadow.cpp's kCoverCodes) behind the caster's
// visible, often lit, surface: its cover passed that surface along a line of pixels
// (tests/hard_cases/audit/pl1_*; /work/aud4 seed 5006: two tilted boxes through each other,
// 0.206% of the receiver pixels). The shadow polygons leave out every such region: what they
// lose there the camera cannot see. World space: the region lies in the receiver's plane, each
// edge a plane through the camera, dot(normal, p) >= offset inside, normal of unit length.
struct HiddenRegion {
  std::array<glm::vec3, 6> normal;
  std::array<float, 6> offset{};
  std::array<float, 6> overlap{};  // metres: a pixel at the edge's far end (see subtract_hidden)
  std::size_t n = 0;
};

// The camera as the hidden regions need it, world space: its position, and its near plane as the
// points p with dot(forward, p) >= near_offset (forward: unit, from the camera to its target).
struct CameraCut {
  glm::vec3 position{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};
  float near_offset = 0.0f;
};

// `pieces` less `region` (planar_hidden.cpp).
void subtract_hidden(std::vector<SmallPolygon> &pieces, const HiddenRegion &region,
                     std::vector<SmallPolygon> &kept, SmallPolygon &scratch);

// Every region `caster`'s drawn surface hides of receiver triangle `r`'s plane where it passes
// through it (none when the camera is behind the plane: the covers there are culled), its part
// nearer than the camera's near plane left out. `pixel` is the tangent of a pixel's angle
// through the camera.
void hidden_regions(const PlanarCaster &caster, const ReceiverTriangle &r,
                    const CameraCut &camera, float pixel, std::vector<HiddenRegion> &hidden,
                    SmallPolygon &polygon, SmallPolygon &scratch);

}  // namespace gs::planar
