// Internal to the depth-map technique: the interior error beside the shadow edges a caster's
// silhouette throws onto a receiver close behind it, within the reach of the map's biases. The
// slope term (bounded to depth_bias_bound texels' widths at the caster's depth) carries the
// caster's depths back along the light's rays, and the receiver-plane bias brings the receiver's
// forward; where the gap between them is smaller, the texels along the edge compare lit and the
// shadow's edge moves in by a texel or more. shadow_edge_error.h finds the texture's edge from
// the texel centres the caster covers, with no bias, and depth_map_contacts.h walks only from
// lines where the caster meets the receiver, so a caster hovering over one saw neither:
// near_20602 (crumple 0.8 to 1.3 m over the dunes, 5 m from the light, a bound of 1.3 m there:
// 0.129% interior false light served) and sunk-extra-lights_17212 (box0 0.3 to 0.8 m over the
// dunes, 7 m from light 2, 0.121% served). The estimate replays the map's lookup
// (depth_map_replay.h) on the receiver across each such edge. Spaces: world (meshes, planes,
// rays in double); the map's texture coordinates (s, t, r, q; s/q and t/q times the side are
// texels, r/q the stored depth 0..1); screen pixels (footprint_screen_pixels).
#pragma once

#include "techniques/depth_map/depth_map_contacts.h"
#include "techniques/depth_map/depth_map_footprint.h"
#include "techniques/depth_map/depth_map_passes.h"

#include <vector>

namespace gs::depth_map {

// Per scene object (zero for one that casts nothing, or whose shadow edges lie beyond the
// biases' reach), with the receiver that has the most: the interior error the `side << k`-texel
// map of `frustum` (light `light`, the technique's `options`; k = 0 .. 3) makes across the
// shadow edges that the silhouette segments of `footprints` (caster_footprints) throw onto the
// first surface behind them along the light's rays, where that surface receives, is not the
// caster itself and faces the light, and where a texel holding the caster within two texels of
// the edge stores it (its slope term and facet push as drawn, or the bounded copy) at or beyond
// that surface's lowered depth there: within the biases' reach. The edges are sampled about a
// pixel apart on screen; at each sample the receiver is walked across the edge on both sides (in
// its plane, each point brought back onto the receiver along the light's ray), and each point the
// camera sees, where that caster alone decides for this light and no other light's shadow holds
// it (the frame's mask is every light's shadow at once), compares a ray to the light with the
// replayed lookup. The runs of wrong points from the edge count as the screen they cover (as
// wide along the edge as the sample's share of it), once, beyond the band of a visible shadow
// edge from the sample's own edge and outside the error measure's band as the truth draws it
// (depth_map_frame_truth.h: beside other edges, and surfaces' outlines the truth turns at).
std::vector<ContactError> hover_errors(const Scene &scene, const std::vector<WorldMesh> &meshes,
                                       const std::vector<CasterFootprint> &footprints,
                                       const LightFrustum &frustum, const SpotLight &light,
                                       int side, const TechniqueOptions &options);

}  // namespace gs::depth_map
