// Per-vertex lighting of the scene pass (step 4): ambient plus each spotlight's diffuse term,
// with a smooth cone edge and no shadowing (shadows are what the techniques add).
#pragma once

#include "scene.h"

namespace gs {

// Colour 0..1 of a surface point (world position and unit normal) with base colour `albedo`.
glm::vec3 shade_vertex(const Scene &scene, const glm::vec3 &world, const glm::vec3 &normal,
                       const glm::vec3 &albedo);

// How much of `light` reaches `world` before any occluder: cone and facing, 0..1. Shared with
// the ground truth, so "lit" means the same thing everywhere.
float spot_factor(const SpotLight &light, const glm::vec3 &world);

}  // namespace gs
