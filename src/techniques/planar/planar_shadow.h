// The article's "easy answer" (Nguyen 1999, Listing 1): every caster triangle facing a light is
// projected from the light onto the plane of every receiver triangle facing it and clipped to
// that triangle's edges; the polygons are drawn flat black over the lit scene, each pixel
// darkened once per light however many polygons cover it.
#pragma once

#include "scene/scene.h"
#include "techniques/technique.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace gs {

// Step 1 stops clipping after this many caster/receiver triangle pairs per frame (pairs that
// survive the cheap rejections: cone, facing, bounding boxes in the light's view, plane side),
// keeping the frame's cost bounded; the rest of the pairs cast nothing and a warning says so.
// The fighter scene clips about 7,000 pairs a frame in some 2 ms; a frame at the limit takes of
// the order of 0.1 s.
constexpr std::size_t kMaxClippedPairs = 400000;

// One light's shadow polygons. Each is convex, lies in its receiver triangle's plane, and is
// wound like that triangle (counter-clockwise seen from the light).
struct ShadowPolygons {
  struct Polygon {
    std::uint32_t first = 0, count = 0;  // a run of `vertices`
    std::uint32_t receiver = 0;          // index into scene.objects
    std::uint32_t triangle = 0;          // index into that object's mesh.triangles
  };
  std::vector<glm::vec3> vertices;  // world space
  std::vector<Polygon> polygons;
};

struct PlanarShadows {
  std::vector<ShadowPolygons> lights;  // one per scene light, same order
  std::size_t pairs_clipped = 0;       // pairs that reached the projection and clipping
  std::size_t pairs_skipped = 0;       // pairs beyond kMaxClippedPairs, left without a shadow
};

// Step 1: Listing 1 for every light, caster (shadow_mesh when it has one) and receiver.
PlanarShadows project_and_clip_casters(const Scene &scene);

std::unique_ptr<ShadowTechnique> make_planar_shadow(const TechniqueOptions &options);

}  // namespace gs
