// Internal to the depth-map technique: the light's depth pass draws a caster's corners pushed
// away from the light along their rays where its surface turns away from the light between two
// facets (depth_map_facets.cpp), so a receiver point near such an edge does not read the other
// facet's nearer depth as its own shadow. Spaces: world.
#pragma once

#include "techniques/depth_map/depth_map_passes.h"

#include <vector>

namespace gs::depth_map {

// `mesh`'s world positions as the `side`-texel map of `frustum` (light at `light`) draws them.
std::vector<glm::vec3> facet_pushed_positions(const WorldMesh &mesh, const LightFrustum &frustum,
                                              const glm::vec3 &light, int side);

}  // namespace gs::depth_map
