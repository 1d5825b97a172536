// Receivers a caster reaches through (a post through a floor, a ball sunk into a mound, a fist
// in another fighter): the part of the caster beyond the receiver's surface, seen from the
// light, is behind the receiver and casts nothing on it, but a texture of the whole caster would
// project it onto the receiver all the same. The projected technique gives each such pair its own
// texture (projected_shadow.cpp): for a planar receiver the caster clipped to the light's side of
// its plane; for any other the caster drawn only where it is nearer the light than the
// receiver's light-facing surface (step 1 draws that surface into its depth buffer first,
// receiver_mask_surface.cpp). docs/hard_cases_results.md measures both and their cost.
#pragma once

#include "techniques/projected/contact_strips.h"
#include "techniques/projected/projected_shadow.h"
#include "techniques/light_passes/scene_pass.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace gs {

struct PiercedReceiver {
  std::size_t receiver = 0;  // index into scene.objects
  bool planar = true;        // false: masked by the receiver's surface instead of a plane
  glm::vec4 plane{0.0f};     // planar: world space, dot(plane, (p, 1)) > 0 on the light's side
  bool casts = false;        // some of the caster lies on the light's side of the receiver
  // Not planar: per triangle of the caster's mesh (caster_mesh), 1 where it passes through the
  // receiver's surface (its cut by the surface is an edge of the shadow).
  std::vector<std::uint8_t> caster_crossing;
  // Not planar: per triangle of the receiver's mesh, 1 where the caster's surface passes
  // through it.
  std::vector<std::uint8_t> receiver_crossing;
  // Not planar: where a caster triangle and a receiver triangle pass through each other, the
  // segment (world) they share, with each one's unit normal (as wound, world): step 1 keeps the
  // caster out of the texels beside it on the caster's inside (contact_strips.h).
  std::vector<ContactSegment> contacts;
};

// The plane of a flat caster (world space, unit normal, positive on the light's side): all the
// vertices of its caster_mesh within 1e-5 of its extent (the world box around its model box) of
// the plane of its first triangle with an area, the light at `light_position` (world) off it.
// Nothing on the light's side of that plane is in its shadow, so step 3 clips its receivers to
// the far side (compute_receiver_coords) and no receiver's surface masks its texture
// (pierced_receivers, receiver_layers).
std::optional<glm::vec4> planar_caster(const SceneObject &caster, const glm::vec3 &light_position);

// The receivers of `caster`'s shadow from the light at `light_position` (world) that it reaches
// through. Planar ones: all their vertices in one plane (within 1e-5 of their extent) with the
// light off it, and a vertex of the caster on the far side of that plane from the light by more
// than 1e-4 of the caster's size. The others: the caster's surface and theirs pass through each
// other (an edge of one through a triangle of the other, its ends more than that on either side);
// none for a flat caster (`caster_plane`, its planar_caster for this light), whose plane step 3
// clips them to instead.
std::vector<PiercedReceiver> pierced_receivers(const Scene &scene, const FrameGeometry &frame,
                                               std::size_t caster,
                                               const glm::vec3 &light_position,
                                               const std::optional<glm::vec4> &caster_plane);

// The non-planar half of pierced_receivers: whether `caster` (world vertices `caster_world` and
// `caster_triangles` of its caster_mesh, bounds low..high, `tolerance` metres) passes through
// `receiver`'s surface, filling `pierced` (caster_crossing, casts) when it does. Only triangles
// inside both meshes' bounds are tested, through a grid of that box.
bool pierced_surface(const ProjectedObject &receiver, const std::vector<glm::vec3> &caster_world,
                     const std::vector<glm::uvec3> &caster_triangles, const glm::vec3 &low,
                     const glm::vec3 &high, float tolerance, PiercedReceiver &pierced);

// The caster's farthest vertex (caster_mesh) from the light: light view depth -z, metres, for
// `light_view` (world to light view). A receiver masking the caster takes the masked texture
// nearer the light than this and the whole caster's beyond it (compute_receiver_coords).
float farthest_depth(const SceneObject &caster, const glm::mat4 &light_view);

// Step 1 for a non-planar pierced receiver (render_caster_from_light with a SurfaceMask, after
// its clear of colour and of depth to the farthest W): the receiver's triangles facing the light, clipped to the light's view, drawn into
// the depth buffer only where the caster can draw (within a texel of view.covered's cells), and the depth test left at LESS with depth writes off, so the caster
// draws only where it is nearer the light. Every vertex step 1 draws then takes its W from
// depth_oow.
// With `farthest`, the surface keeps its farthest light-facing layer per pixel (depth test
// GREATER on a clear to the nearest W) and the caster is then tested against that; its fins
// along the outline from the light carry that layer's W over the texels just beyond it.
// With `triangles`, only the receiver's triangles whose entry is not 0 (SurfaceMask::triangles).
void draw_mask_surface(const LightView &view, const ProjectedObject &receiver, bool farthest,
                       const std::vector<std::uint8_t> *triangles = nullptr);
// 1/W for a light view w (metres along the light's axis): w over a unit of half the caster's
// front distance, so the W-buffer (1/W in [0, 1]) keeps its precision for a light nearer than a
// metre.
float depth_oow(const LightView &view, float light_w);

}  // namespace gs
