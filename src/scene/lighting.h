// Per-vertex lighting of the scene pass (step 4): ambient plus each spotlight's diffuse term,
// with a smooth cone edge (or the beam map) and distance attenuation, and no shadowing (shadows
// are what the techniques add).
#pragma once

#include "scene/scene.h"

namespace gs {

// Colour 0..1 of a surface point (world position and unit normal) with base colour `albedo`.
glm::vec3 shade_vertex(const Scene &scene, const glm::vec3 &world, const glm::vec3 &normal,
                       const glm::vec3 &albedo);

// One light's direct term at a vertex on a white surface, for passes that apply the light's beam
// map or slide as a texture: colour x Lambert diffuse, x the cone for a light without a beam map,
// x the distance attenuation unless the pass applies it per pixel; a slide projector's colour
// where the surface faces it.
glm::vec3 vertex_light_term(const SpotLight &light, const glm::vec3 &world, const glm::vec3 &normal,
                            bool attenuation_per_pixel);

// How much of `light`'s beam reaches `world` before any occluder: the cone, or the beam map's
// intensity there, 0..1; attenuation with distance not included. Shared with the ground truth,
// so "lit" means the same thing everywhere.
float spot_factor(const SpotLight &light, const glm::vec3 &world);

}  // namespace gs
