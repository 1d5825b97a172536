// Where a closed caster passes through a receiver that masks its texture (pierced_receivers.h),
// the receiver's surface meets the caster's light-facing surface along a line. On one side of it
// the receiver lies outside the caster and the caster's surface is behind it (lit); on the other
// the receiver lies inside the caster, just behind that surface (in shadow, but no camera
// outside the caster sees it). The masked texture holds that cut exactly, but a texel is wide:
// bilinear filtering (and a point sample's texel) beside the line darkens the receiver's visible
// side up to a texel and a half from it, which under a grazing light is many screen pixels of
// the receiver (issue 14, grazing_6001: boxes and a fighter through each other in the dunes).
// And on the visible side the caster's triangle lies behind the surface by less than a W-buffer
// code near the line, so step 1's depth test there is a coin toss. Step 1 keeps that caster triangle out of a strip of
// texels on both sides of the line, as deep as filtering reaches: the visible side reads no
// covered texel from it. An open caster (a sheet, drawn from both sides) cut by the receiver is
// the same but for its hidden side: the receiver there lies behind the sheet's part above it,
// in shadow, and the strip is kept only where the camera sees none of it (the sheet hides it;
// issue 14, meshes_12312: a crumpled sheet through dunes under a low light, 0.111% false shadow
// on the dunes in front of it). A closed caster's hidden side is seen too when the camera's
// near plane meets the caster's inside (the camera in a crate, stencil17_sv1): there the strip
// on that side is kept only where the camera sees none of it. Spaces: world in; the light's
// size x size Glide screen (texels, y down) with 1/W from depth_oow out.
#pragma once

#include <glide.h>
#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace gs {

struct LightView;
struct ProjectedObject;
struct SceneObject;

// A segment (world) shared by a receiver triangle and a caster triangle that pass through each
// other, with the unit normals (world) of the receiver's and the caster's triangle as wound.
struct ContactSegment {
  glm::vec3 a, b;
  glm::vec3 receiver_normal;
  glm::vec3 caster_normal;
};

// A point (world) where an edge of one of a receiver triangle and a caster triangle passes
// through the other, with the two triangles' indices (any numbering that tells triangles apart)
// and their unit normals (world) as wound.
struct ContactPoint {
  std::size_t receiver_triangle, caster_triangle;
  glm::vec3 point;
  glm::vec3 receiver_normal, caster_normal;
};

// Per pair of triangles with crossing points, the segment they share: its ends are the pair's
// two points farthest apart (a pair with a single point gives none). In order of the pairs.
std::vector<ContactSegment> contact_segments(std::vector<ContactPoint> points);

// Texels from the line the strip reaches on each side (and beyond each end): bilinear
// filtering reads texel centres less than one texel away on each axis, and the half texel more
// absorbs the shim's 1/16 snapping, as the receiver outline's fins do (receiver_mask_surface.cpp).
constexpr float kContactStripTexels = 1.5f;
// How much nearer the light than the caster's and the receiver's planes a strip's corners lie,
// as a share of their light clip w: a few W-buffer codes (4096 an octave). A receiver point
// behind an open caster's surface by less than that is on the cut, where step 1's depth test
// cannot tell its sides apart (contact_strip_rays.h).
constexpr float kContactStripDepthShare = 2e-3f;

// The strips of `contacts` whose receiver triangle faces the light, and its caster triangle too
// when the caster is `closed` (step 1 culls its other faces; an open one is drawn whole), in the
// light's screen of `view`, each a quad a little nearer the light than the caster's triangle
// (and the receiver's) at its corners, so the caster fails step 1's depth test there. A strip
// keeps only that triangle's plane out: a farther part of the caster in front of the receiver
// still shadows it. Only the parts of a strip (pieces about a texel long, each side of the cut
// apart) with no point of `receiver` within the filter's reach that the camera (at `camera`,
// world; `camera_clip` world to its clip space) may see in `caster`'s shadow are kept
// (contact_strip_rays.h): a strip lights no receiver point the caster shadows that is seen.
std::vector<std::array<GrVertex, 4>> contact_strips(const LightView &view,
                                                    const std::vector<ContactSegment> &contacts,
                                                    const SceneObject &caster, bool closed,
                                                    const ProjectedObject &receiver,
                                                    const glm::vec3 &camera,
                                                    const glm::mat4 &camera_clip);

}  // namespace gs
