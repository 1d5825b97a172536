// The depth a clipped receiver piece takes in step 5 and in the mask: that of the triangles step
// 4 drew for its receiver triangle, as the shim rasterised them. A piece's own vertices lie on
// the receiver's plane in the world, but each is snapped to 1/16 pixel on its own, and on a
// surface seen nearly edge-on a sixteenth of a pixel is many W-buffer codes: a long thin piece
// strayed from step 4's depth by more than any small bias (issue 14, grazing_0105). Spaces:
// Glide screen (pixels, y down, the clip window 0..width, 0..height); depth is the W buffer's
// 1/w without bias.
#pragma once

#include "techniques/light_passes/scene_pass.h"

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

// The receiver triangle's plane seen through the camera: the point of it at a screen position,
// in light view space, and its true 1/w (double throughout).
class ReceiverPlane {
 public:
  ReceiverPlane(const FrameGeometry &frame, const Scene &scene, const glm::mat4 &light_view,
                const glm::vec3 &point, const glm::vec3 &normal);  // world
  bool at(const glm::dvec2 &screen, glm::dvec4 &light_view, double &oow) const;
  glm::vec3 world(const glm::dvec4 &light_view) const;

 private:
  glm::dmat4 screen_to_world_, world_to_light_view_, camera_;
  glm::dvec3 point_, normal_;
  glm::dvec2 pixels_;
};

// A vertex of a clipped receiver piece as step 5 sends it: snapped as the shim snaps it, the
// depth step 4 drew there, and the receiver's world point there (for (s, t) and alpha).
struct DrawnVertex {
  glm::vec2 screen;
  float oow;
  glm::vec3 world;
};
using DrawnPiece = std::vector<DrawnVertex>;

// Step 4's triangles of a receiver triangle (`drawn`) clipped to the piece the shadow may fall
// on (`light_view_planes`: dot(plane, light view position) >= 0), in the screen: each part's
// outline is step 4's own where the triangle's is, so the parts cover the pixels step 4 drew
// for the piece, and each vertex's oow lies on the depth plane of the triangle it came from,
// so the part interpolates the very depth step 4 drew under it. Appends the parts with an area.
void cut_drawn(const std::vector<DrawnTriangle> &drawn, const ReceiverPlane &plane,
               const std::vector<glm::vec4> &light_view_planes, std::vector<DrawnPiece> &out);

}  // namespace gs
