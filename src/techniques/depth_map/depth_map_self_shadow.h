// Internal to the depth-map technique: the false shadow the map casts on a caster's own lit side
// where the light grazes it (acne the biases do not cover). A texel's centre ray a fraction of
// a texel below a point the light meets at a grazing angle can strike the same surface metres
// nearer the light (a dune's crest in front of its lee side), more than the slope term, bounded
// to a few texels (depth_bias_bound), and the receiver-plane bias, capped at the triangle's own
// depth span (depth_map_lookup.h), push apart; nor is it a turn between two facets that the
// facet push (depth_map_facets.h) sees. No silhouette edge or foot is near, so neither
// shadow_edge_error.h nor depth_map_contacts.h counts it. Nor do they count the shadows a caster
// casts on its own lit side from a distance (a dune's crest on the next slope, a step's edge on
// the step below, receivers_23012 and receivers-mixed-lights_23082: 0.145% and 0.129% served):
// depth_map_footprint.cpp leaves the caster's own surface out of the error along its edges, as
// the bias carries a terminator's depths back there (ripples_grazing), and only the false shadow
// such an edge's texels put beyond its band on the lit side counts (the error measure leaves out
// the pixels only their own object shadows). The estimate replays the map's lookup
// (depth_map_replay.h) over the caster's lit triangles the camera sees and compares it with
// rays to the light. Spaces: world (meshes, rays); screen pixels (footprint_screen_pixels).
#pragma once

#include "techniques/depth_map/depth_map_passes.h"
#include "techniques/texel_error/shadow_edge_error.h"

#include <vector>

namespace gs::depth_map {

// Per scene object (zero for one that does not both cast and receive): the screen pixels of its
// triangles that face `light`, which the camera sees, the light reaches past every caster, which
// lie farther than two pixels from any shadow (inside that, a wrong pixel is the band of a true
// edge), and which the lookup
// of the `side << k`-texel map of `frusta[k]` (the technique's `options`; k = 0 .. 3, one
// frustum fitted at each size) shadows, each caster in it as step 1 draws it: counted for the
// caster whose texels say shadow there; on a triangle the light meets farther than
// kGrazingTangent * (the slope bound's reach) from edge-on, only where those are the object's own.
std::vector<EdgeErrorEstimate> self_shadow_errors(const Scene &scene,
                                                  const std::vector<WorldMesh> &meshes,
                                                  const std::vector<LightFrustum> &frusta,
                                                  const SpotLight &light, int side,
                                                  const TechniqueOptions &options);

}  // namespace gs::depth_map
