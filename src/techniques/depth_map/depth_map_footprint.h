// Internal to the depth-map technique: how many screen pixels one texel of a light's depth map
// spans where a caster's shadow edge can lie (near the caster's silhouette from the light), per
// caster, measured with texel_footprint.h as the projected technique measures its texture. A
// caster whose texels are too coarse is left out of the map by name (depth_map_from_light.cpp).
#pragma once

#include "techniques/depth_map/depth_map_passes.h"
#include "techniques/texel_error/shadow_edge_error.h"
#include "techniques/texel_error/texel_footprint.h"

#include <vector>

namespace gs::depth_map {

// The largest footprint accepted by default, measured with `hard_case_sweeps depth-footprint`
// (interior error against the footprint, docs/hard_cases_sweeps.md, "The depth map's texels
// against screen pixels"): every configuration over 0.1% had 5.56 px or more, every one at
// 4.59 px or less was within, with the percentage-closer lookup (GL_LINEAR) and nearest alike.
inline constexpr float kLargestDepthMapFootprintPx = 5.0f;

// One caster's shadow under one light: the coarsest sample over the receivers (shadow_footprint,
// the receiver named in it), the interior error its map's texels would make along its shadow's
// edges (shadow_edge_error.h; screen pixels) with the receiver that has the most of it, and the
// caster's index into the scene's objects.
struct CasterFootprint {
  std::size_t caster = 0;
  FootprintSample coarsest;
  EdgeErrorEstimate edge_error;
  std::size_t edge_error_receiver = 0;
  // Its silhouette from the light (world), each edge once, for the estimates that replay the
  // map's lookup across the shadow edges they throw (depth_map_hover.h).
  std::vector<SilhouetteSegment> segments;
};

// Per caster of `meshes` (world space) that casts: the footprint of the `side`-texel map of
// `frustum` on every receiving triangle that faces `light`, lies in its beam, in the map's
// frustum, in the camera's view and beyond the caster's nearest point from the light, within
// the lookup's reach of the texture cells the caster's silhouette from the light crosses
// (its edges between a face towards the light and one away, and an open mesh's rim); and on
// the same parts of the other receivers the error along the shadows those silhouette edges
// throw, read by `lookup` (the percentage-closer lookup or the nearest texel). A caster shadows
// itself too, so it is one of its own receivers for the footprint.
std::vector<CasterFootprint> caster_footprints(const Scene &scene,
                                               const std::vector<WorldMesh> &meshes,
                                               const LightFrustum &frustum,
                                               const SpotLight &light, int side,
                                               EdgeLookup lookup);

}  // namespace gs::depth_map
