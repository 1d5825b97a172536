// Step 4 of the article ("render the scene normally") and the per-frame projection it shares
// with the shadow passes: every object's vertices in world space, lit, and projected through
// the camera once, so a second pass over a triangle sends the very same screen vertices and
// passes the LEQUAL depth test on every pixel.
#pragma once

#include "techniques/geometry/projection.h"
#include "scene/scene.h"

#include <glide.h>

#include <vector>

namespace gs {

struct ProjectedObject {
  const SceneObject *object = nullptr;
  std::vector<glm::vec3> world;     // vertex positions, world space
  std::vector<glm::vec3> normal;    // unit normals, world space
  std::vector<unsigned> outside;    // per vertex: one bit per camera clip plane it fails
  std::vector<GrVertex> screen;     // Glide screen vertices, lit (r, g, b); valid when outside == 0
};

struct FrameGeometry {
  glm::mat4 view_projection{1.0f};  // world to camera clip
  std::vector<ProjectedObject> objects;
};

FrameGeometry project_scene(const Scene &scene);

// Clips a world-space polygon through the camera (near plane and guard band) and gives its
// screen vertices (x, y, oow only), one per surviving vertex of `polygon`, whose world
// positions and `extra` attributes the caller uses to fill the other fields.
void project_camera_polygon(const FrameGeometry &frame, const Scene &scene,
                            std::vector<ClipVertex> &polygon, std::vector<ClipVertex> &scratch,
                            std::vector<GrVertex> &screen);
// Draws a convex screen polygon as a fan, clipped to the clip window as the hardware does.
void draw_fan(const std::vector<GrVertex> &polygon);

// The Glide state of the scene pass (Listing 4: W-buffer, LEQUAL, depth writes, back faces
// culled) and the pass itself: clear, then every object Gouraud-shaded.
void set_scene_state();
void render_scene(const Scene &scene, const FrameGeometry &frame);
// The scene pass's depth buffer again, colour left as it is: depth cleared, then every triangle
// with the very vertices render_scene sends (so every pixel gets the same depth), colour writes
// off. Leaves the scene pass's state with colour writes back on (alpha off).
void render_scene_depth(const Scene &scene, const FrameGeometry &frame);

// Draws one triangle of a projected object, clipping through the camera when it must.
void draw_object_triangle(const FrameGeometry &frame, const Scene &scene,
                          const ProjectedObject &object, const glm::uvec3 &triangle);

}  // namespace gs
