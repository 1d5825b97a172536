// Internal to the depth-map technique: the meshes every pass draws, a light's fitted frustum and
// the frame's GL passes, shared by depth_map_from_light.cpp (step 1: frusta and maps) and
// depth_map_shadow.cpp (steps 2 and 3, the mask). Spaces: world (the meshes); light view and
// light clip, GL convention (the frustum's matrices).
#pragma once

#include "techniques/plain_gl/gl_api.h"
#include "techniques/geometry/edge_mesh.h"
#include "techniques/technique.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace gs::depth_map {

// Light clip space to the map's texture coordinates: s, t, r = 0.5 (x, y, z) + 0.5 w, q = w.
inline glm::mat4 texture_from_clip() {
  return glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) *
         glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
}

// An object's vertices in world space: the arrays every pass draws.
struct WorldMesh {
  const SceneObject *object = nullptr;
  std::vector<glm::vec3> position;  // world
  std::vector<glm::vec3> normal;    // world, unit
  // A caster welded into one surface (model space) and its welded positions in world space,
  // made once a frame: every light's silhouette (depth_map_footprint.cpp) and facet push
  // (depth_map_facets.cpp) walk it. Empty for an object that casts no shadow.
  EdgeMesh surface;
  std::vector<glm::vec3> surface_world;  // world, one per surface.positions
};

// A light's frustum: along the light's axis, across the part of the cone's square (the beam's
// circle inscribed) that the casters inside the beam cover, near and far fitted to the scene:
// far beyond every vertex, near before every caster's vertex in front of the light. A receiver
// nearer than that has r < 0, which compares as lit.
struct LightFrustum {
  glm::mat4 view{1.0f};        // world to light view
  glm::mat4 projection{1.0f};  // light view to light clip
  std::string problem;         // why the light has none, for the user; empty when it has one

  // A texel's width in metres per metre of light-view depth, for a map of `side` texels (the
  // wider of the frustum's two tangent spans).
  float texel_per_metre(int side) const {
    return std::max(2.0f / projection[0][0], 2.0f / projection[1][1]) /
           static_cast<float>(std::max(side, 1));
  }
};

// The GL objects and passes of one frame. Textures and framebuffer are made and deleted with
// it, inside one glideShimBeginGL .. glideShimEndGL, so none outlives the window it was made in.
class Passes {
 public:
  Passes(const GlApi &gl, const Scene &scene, const TechniqueOptions &options);
  ~Passes();
  Passes(const Passes &) = delete;
  Passes &operator=(const Passes &) = delete;

  // Step 1; a light left without its map is an error (it casts no shadow), and so is a caster
  // left out of a light's map because its texels are too coarse for the screen where its shadow
  // edges lie (depth_map_footprint.h).
  void depth_from_lights(std::vector<std::string> &warnings, std::vector<std::string> &errors);
  // After step 1: the most screen pixels a map texel spanned where a shadow edge can lie, over
  // every light and caster, drawn or left out (what the footprint limit bounds).
  float texel_footprint_px() const { return texel_footprint_px_; }
  void ambient_pass();                                         // step 2
  void lit_passes();                                           // step 3
  // The mask over the frame's depth buffer (after steps 1-3 of the same scene).
  void mask_passes();

 private:
  void use_camera();
  // Unit 0: light `light`'s map compared with `compare` (LEQUAL: 1 where lit), its coordinates
  // per corner from draw_receiver; unit 1: the q gate. The gate's texgen planes are given while
  // the modelview is the camera's view, so they act on world coordinates (Everitt et al.,
  // Appendix A).
  void bind_shadow_units(std::size_t light, GLenum compare);
  // A receiver's triangles, three world corners each, with their colours and the bound light's
  // map coordinates, lowered by each triangle's own depth slope (depth_map_lookup.h) when the
  // receiver `casts`. A receiver that casts nothing has no depths of its own in the map, so it
  // has no acne to take off; lowered, it would only come out nearer the light than the caster
  // surfaces it meets, up to about a texel past the contact, which under a grazing light spans
  // far across it (grazing_2046: 0.46% interior false light along a sunk ball's foot).
  void draw_receiver(const std::vector<glm::vec3> &corners, const std::vector<glm::vec4> &colors,
                     bool casts);
  void release_shadow_units();
  void draw(const WorldMesh &mesh, const std::vector<glm::vec4> &colors);
  // Step 1: a caster's triangles at `positions` (world), with whatever offset is set.
  void draw_caster(const WorldMesh &mesh, const std::vector<glm::vec3> &positions);
  float farthest_from(const SpotLight &light) const;  // largest light-space depth, metres

  const GlApi &gl_;
  const Scene &scene_;
  const TechniqueOptions &options_;
  std::vector<WorldMesh> meshes_;
  std::vector<LightFrustum> frustums_;  // per light
  std::vector<GLuint> maps_;            // per light; 0: the light casts no shadow
  std::vector<int> sides_;              // per light, the map's side in texels
  glm::mat4 to_map_{1.0f};              // world to the bound light's texture coordinates
  int bound_side_ = 1;                  // the bound light's map side, texels
  GLuint framebuffer_ = 0;              // step 1's, depth only
  GLuint gate_ = 0;                     // the q gate's step texture
  GLint target_framebuffer_ = 0;        // the shim's, holding Glide's back buffer
  GLint window_[4] = {};                // the shim's viewport: the whole window
  float texel_footprint_px_ = 0.0f;
};

}  // namespace gs::depth_map
