// The depth a clipped receiver piece takes in step 5 and in the mask: that of the triangles step
// 4 drew for its receiver triangle, as the shim rasterised them. A piece's own vertices lie on
// the receiver's plane in the world, but each is snapped to 1/16 pixel on its own, and on a
// surface seen nearly edge-on a sixteenth of a pixel is many W-buffer codes: a long thin piece
// strayed from step 4's depth by more than any small bias (issue 14, grazing_0105). Spaces:
// Glide screen (pixels, y down, the clip window 0..width, 0..height); depth is the W buffer's
// 1/w without bias.
#pragma once

#include "techniques/scene_pass.h"

#include <glide.h>
#include <glm/glm.hpp>

#include <vector>

namespace gs {

// One triangle as the shim queues it: positions snapped to 1/16 pixel, and the unbiased W
// depth (1/w, at most 1) at each corner.
struct DrawnTriangle {
  glm::vec2 p[3];
  float depth[3];
};

// Step 4's triangles for `triangle` of `object` as draw_object_triangle sends them (its screen
// vertices, or the fan of its polygon clipped through the camera), each through the shim's
// guDrawTriangleWithClip: snapped, clipped to the clip window (0, 0, width, height) and snapped
// again as it does, and without those it drops (zero area, or culled as the scene culls).
void step4_triangles(const FrameGeometry &frame, const Scene &scene, const ProjectedObject &object,
                     const glm::uvec3 &triangle, std::vector<DrawnTriangle> &out);

// Cuts a convex screen polygon (a clipped piece of the receiver triangle `drawn` comes from:
// x, y unsnapped; oow, a and tmuvtx[0] set) along the triangles of `drawn`, and appends to
// `out` each part that has an area, its vertices snapped as the shim snaps them and their oow on
// the depth plane of the drawn triangle the part lies in: the part then interpolates the very
// depth step 4 drew under it. The other fields are interpolated linearly in the screen, as the
// rasteriser would have across the whole piece; with `q_is_oow` (Listing 3's per-vertex (s, t),
// which the shim divides by oow) sow and tow are scaled with oow, so (s, t) stays.
void cut_along_drawn(const std::vector<GrVertex> &polygon, const std::vector<DrawnTriangle> &drawn,
                     bool q_is_oow, std::vector<std::vector<GrVertex>> &out);

}  // namespace gs
