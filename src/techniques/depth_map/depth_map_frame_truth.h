// Internal to the depth-map technique: the error measure's band (measure/metrics.h), for the
// estimates that replay the map at pixels (depth_map_lowered.h) or along runs on screen
// (depth_map_hover.h). The measure excuses a wrong pixel within one (Chebyshev) of a boundary
// pixel: one whose 4-neighbour the truth calls otherwise. Its boundary runs along every shadow
// edge, and also along the outline of a surface against another the truth calls otherwise (a
// thin sliver of shadow beside the caster that throws it, seen from the side, is all band). The
// truth here is found as the ground truth finds it, from the camera's ray through the pixel's
// centre and rays to the lights. Spaces: world (rays in double); camera clip and NDC; screen
// pixels (x right, rows from the top, as the measure's masks).
#pragma once

#include "techniques/depth_map/depth_map_replay.h"
#include "techniques/geometry/light_beam.h"

#include <map>
#include <utility>
#include <vector>

namespace gs::depth_map {

class FrameTruth {
 public:
  // `bodies`: every object of `meshes` as a ray body (ray_bodies), kept by reference.
  FrameTruth(const Scene &scene, const std::vector<WorldMesh> &meshes,
             const std::vector<RayBody> &bodies)
      : scene_(scene), meshes_(meshes), bodies_(bodies) {
    const FootprintSpace space = camera_screen(scene);
    clip_to_world_ = glm::inverse(glm::dmat4(space.camera_clip));
    for (const SpotLight &each : scene.lights) {
      if (!each.is_projector()) lights_.emplace_back(&each, light_beam(each));
    }
  }

  // The near and far ends (world) of the camera's ray through pixel (x, y)'s centre.
  void camera_ray(int x, int y, dvec3 &from, dvec3 &to) const {
    const glm::dvec2 ndc((x + 0.5) / scene_.width * 2.0 - 1.0, 1.0 - (y + 0.5) / scene_.height * 2.0);
    const glm::dvec4 near_end = clip_to_world_ * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 far_end = clip_to_world_ * glm::dvec4(ndc, 1.0, 1.0);
    from = dvec3(near_end) / near_end.w, to = dvec3(far_end) / far_end.w;
  }

  // The truth at pixel (x, y): -1 where the camera sees no surface, else 1 where a light whose
  // beam holds the surface seen, facing it, is blocked there by another object that casts, 2
  // where none is but the surface's own object blocks one (its shadow on itself, which the
  // measure leaves out), and 0 where nothing does. Found once a pixel.
  int at(int x, int y) {
    if (x < 0 || y < 0 || x >= scene_.width || y >= scene_.height) return -1;
    const auto known = truths_.find({x, y});
    if (known != truths_.end()) return known->second;
    dvec3 from, to;
    camera_ray(x, y, from, to);
    double nearest = 1.0;
    std::size_t seen = bodies_.size(), triangle = 0;
    for (std::size_t m = 0; m < bodies_.size(); ++m) {
      double t = nearest;
      std::size_t k = 0;
      if (bodies_[m].triangles.nearest(from, to - from, 0.0, t, k)) nearest = t, seen = m, triangle = k;
    }
    int truth = -1;
    std::size_t lights = lights_.size();
    if (seen < bodies_.size()) {
      const glm::uvec3 &t = meshes_[seen].object->mesh.triangles[triangle];
      const dvec3 a(meshes_[seen].position[t.x]), b(meshes_[seen].position[t.y]),
          c(meshes_[seen].position[t.z]);
      const dvec3 face = glm::cross(b - a, c - a), point = from + (to - from) * nearest;
      truth = 0;
      bool own = false;
      // A surface that receives no shadow is lit wherever a light reaches it.
      if (!meshes_[seen].object->receives_shadow) lights = 0;
      for (std::size_t l = 0; l < lights && truth == 0; ++l) {
        const dvec3 light(lights_[l].first->position);
        if (!(glm::dot(face, light - a) > 0.0) ||
            !inside_planes(lights_[l].second.inner, glm::vec3(point))) {
          continue;
        }
        for (std::size_t m = 0; m < bodies_.size() && truth == 0; ++m) {
          if (m != seen && bodies_[m].casts && blocks(bodies_[m], light, point - light)) truth = 1;
        }
        if (truth == 0 && bodies_[seen].casts && blocks(bodies_[seen], light, point - light)) own = true;
      }
      if (truth == 0 && own) truth = 2;
    }
    truths_.emplace(std::make_pair(x, y), truth);
    return truth;
  }

  // Whether the measure's band holds pixel (x, y): a pixel within one of it that is a boundary
  // pixel, one the measure counts (truth 0 or 1) whose 4-neighbour it counts too and calls
  // otherwise, or a lit one beside its shadow on itself. Found once a pixel.
  bool in_band(int x, int y) {
    const auto known = bands_.find({x, y});
    if (known != bands_.end()) return known->second;
    bool band = false;
    for (int dy = -1; dy <= 1 && !band; ++dy) {
      for (int dx = -1; dx <= 1 && !band; ++dx) {
        const int here = at(x + dx, y + dy);
        if (here != 0 && here != 1) continue;
        for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
          const int there = at(x + dx + d.x, y + dy + d.y);
          if (((there == 0 || there == 1) && there != here) || (here == 0 && there == 2)) band = true;
        }
      }
    }
    bands_.emplace(std::make_pair(x, y), band);
    return band;
  }

 private:
  const Scene &scene_;
  const std::vector<WorldMesh> &meshes_;
  const std::vector<RayBody> &bodies_;
  glm::dmat4 clip_to_world_{1.0};
  std::vector<std::pair<const SpotLight *, LightBeam>> lights_;
  std::map<std::pair<int, int>, int> truths_;
  std::map<std::pair<int, int>, bool> bands_;
};

}  // namespace gs::depth_map
