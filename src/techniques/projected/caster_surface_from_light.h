// The caster's surface as the light sees it, to tell a receiver polygon that lies wholly nearer
// the light than every part of the caster on the light's rays through it (a post standing on a
// table top, for the table's texture; a cube over a plate). No point of such a polygon is in the
// caster's shadow, so step 3 does not shade it at all: the texture's texels cannot draw its
// outline in the caster's shadow (the mask, pierced_receivers.h) finer than a texel, and on a
// face nearly edge-on to the light a texel spans many pixels (issue 14, posts_on_table turned
// -20 degrees: 0.24% interior false shadow).
// Spaces: light clip in (NDC x, y and w, metres along the light's axis; 1/w is linear in NDC on
// a plane, so the depth difference of two planes over a convex region is largest at a corner).
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace gs {

class CasterSurfaceFromLight {
 public:
  // `light_clip`: world to the light's clip space (LightView::projection * view). All of the
  // caster's shadow mesh (caster_mesh, both sides), unclipped: more surface than step 1 draws,
  // so a polygon judged free of it is free of the texture's shadow too.
  CasterSurfaceFromLight(const SceneObject &caster, const glm::mat4 &light_clip);
  // Any mesh (model space, placed by `model_to_world`), both sides: a receiver's own drawn
  // surface, to tell its triangles that no other part of it hides from the light. With
  // `nearest_w` > 0 (light clip w, metres), only what the mask draws of it (draw_mask_surface:
  // beyond the caster's front, inside the view's square): faces wholly nearer than that, wholly
  // to one side of the square or reaching to or behind the light's plane are left out instead
  // of making every answer unsure (a heightfield around the light).
  CasterSurfaceFromLight(const Mesh &mesh, const glm::mat4 &model_to_world,
                         const glm::mat4 &light_clip, float nearest_w = 0.0f);

  // False only when no point of the convex polygon (light clip corners in order, `count` of
  // them) has a caster surface nearer the light than itself by more than touching (a relative
  // kTouch of its depth: a post's foot on the table top). True when unsure (a corner at or
  // behind the light's plane, or the caster reaching there).
  bool may_shadow(const glm::vec4 *light_clip, std::size_t count) const;
  // may_shadow of the triangle `triangle` (an index into `receiver`'s mesh) whose light clip
  // corners are `corners` (this matrix times the receiver's world vertices this frame: the same
  // at every call for that triangle), answered once and then remembered: the caster's textures
  // that share this surface (a receiver's two depth bands) ask about the same triangles.
  bool may_shadow_triangle(const SceneObject &receiver, std::size_t triangle,
                           const glm::vec4 (&corners)[3]) const;

 // A corner of a receiver polygon as may_shadow clips it (light NDC).
  struct PolygonCorner {
    glm::vec2 ndc;
    float inverse_w;  // the receiver polygon's 1 / w there
  };

 private:
  struct Face {
    glm::vec2 a, to_b, to_c;  // NDC: a corner and the edges from it
    float area = 0.0f;        // twice the signed NDC area, never near 0 (those are dropped)
    glm::vec3 inverse_w;      // 1 / w at the three corners
    glm::vec2 low, high;      // NDC box
    // For may_shadow's tests that skip a face without clipping (face_can_shadow), all NDC: the
    // largest 1 / w at a corner, the largest |coordinate| of a corner, how much 1 / w on the
    // face's plane can move per unit of x and y (|d 1/w / du| |du / dNDC| + the same for v),
    // that plane's 1 / w per unit x and y (in double: the test's own rounding stays far below
    // its margin), and per edge (a to b, b to c, c to a) its start,
    // its normal towards the face's inside (the edge turned by a quarter, not unit) and the
    // edge's |x| + |y|.
    float largest_inverse_w = 0.0f, reach = 0.0f, slope = 0.0f;
    glm::dvec2 gradient{0.0};
    glm::vec2 edge_start[3], edge_normal[3];
    float edge_length[3];
  };
  bool face_can_shadow(const Face &face) const;
  static constexpr int kGrid = 32;  // cells a side over the faces' NDC box
  int cell_of(float ndc, int axis) const;

  bool usable_ = true;
  std::vector<Face> faces_;
  glm::vec2 low_{INFINITY}, high_{-INFINITY};  // NDC box of all faces
  glm::vec2 cell_side_{1.0f};                  // NDC: a grid cell's width and height
  std::vector<std::size_t> start_, items_;     // per cell its faces: items_[start_[c]..start_[c+1])
  mutable std::vector<std::size_t> stamp_;     // per face, the query that last tested it
  mutable std::size_t query_ = 0;
  // may_shadow's polygons, kept so that a query (one per receiver triangle) allocates nothing.
  mutable std::vector<PolygonCorner> polygon_, part_, scratch_;
  // The polygon of the query in hand: its largest |NDC coordinate| and its largest 1 / w.
  mutable float polygon_reach_ = 0.0f, polygon_inverse_w_ = 0.0f;
  // may_shadow_triangle's answers per receiver and triangle: -1 not asked yet, else 0 or 1.
  mutable std::vector<std::pair<const SceneObject *, std::vector<signed char>>> answers_;
};

// One caster's surfaces for the light clip matrices of its textures, each built once: the
// plain and masked textures of a light view part share the matrix (the mask changes only what
// step 1 draws), so step 3 of each reuses the same grid instead of building it again. The same
// for the receivers' own drawn surfaces that step 3 tests a receiver's triangles against: the
// caster's two depth-band textures of a light view (one per band, the same matrix) share them.
// Meant for one frame: the scene's objects must not change while it is in use.
class CasterSurfacesFromLight {
 public:
  explicit CasterSurfacesFromLight(const SceneObject &caster) : caster_(caster) {}
  // The surface for `light_clip` (world to light clip), built at the first call with a matrix
  // of the same bytes.
  const CasterSurfaceFromLight &at(const glm::mat4 &light_clip);
  // `receiver`'s own drawn surface (its `mesh`, placed by its model_to_world, both sides) for
  // `light_clip`, built at the first call for that object with a matrix of the same bytes.
  // `nearest_w`: the constructor's, the same at every call for one matrix.
  const CasterSurfaceFromLight &receiver_at(const SceneObject &receiver, const glm::mat4 &light_clip,
                                            float nearest_w);

 private:
  struct ReceiverSurface {
    const SceneObject *receiver;
    glm::mat4 light_clip;  // world to light clip
    std::unique_ptr<CasterSurfaceFromLight> surface;
  };
  const SceneObject &caster_;
  std::vector<std::pair<glm::mat4, std::unique_ptr<CasterSurfaceFromLight>>> built_;
  std::vector<ReceiverSurface> receivers_;
};

}  // namespace gs
