// Stencil shadow volumes after Kwoon's "The Theory of Stencil Shadow Volumes", drawn in plain GL
// (glideShimBeginGL .. glideShimEndGL) into Glide's back buffer: an ambient pass, then per light
// the casters' silhouettes extruded to infinity counted into the stencil buffer (z-pass, or z-fail
// with caps when the camera may be inside a volume), then that light added where the count is 0.
#pragma once

#include "techniques/technique.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace gs {

// Conservatively, whether the camera's near-plane rectangle may lie inside the shadow volume of
// any caster under `light` (then z-pass counts wrongly and z-fail is needed). Each caster's
// volume is bounded by the cone from the light around its bounding sphere, beyond the sphere's
// nearest distance from the light.
bool near_plane_may_be_in_shadow(const Scene &scene, const SpotLight &light);

// The "stencil-volume" technique. Steps: "1 ambient pass", "2 silhouettes and volumes",
// "3 lit pass". Casters that are not closed are skipped with a warning (once per name).
std::unique_ptr<ShadowTechnique> make_stencil_volume_shadow(const TechniqueOptions &options);

}  // namespace gs
