// Internal to the depth-map technique: the false light inside a caster's shadow on receiver
// triangles the light grazes. A receiver that casts compares its depth lowered by its own depth
// change across a texel (the receiver-plane bias, depth_map_lookup.h), up to its triangle's whole
// depth span; where the light grazes the triangle that is most of its extent along the light's
// rays, and a caster closer in front of it than that compares behind it: lit, though the caster
// shadows it, anywhere in the shadow and not only beside its edges, so no estimate along edges
// or feet sees it. sunk-extra-lights_17212: a dunes triangle 0.5 degrees from light 2's rays,
// box0 0.3 to 0.7 m in front of it, 7 pixels of interior false light in the middle of box0's
// shadow (0.121% served). The estimate replays the map's lookup (depth_map_replay.h) at the
// pixel centres of such triangles. Spaces: world (meshes, rays in double); the map's texture
// coordinates (s/q and t/q times the side are texels, r/q the stored depth 0..1); camera clip
// and NDC; screen pixels (x right, rows from the top, as the measure's masks).
#pragma once

#include "techniques/depth_map/depth_map_contacts.h"
#include "techniques/depth_map/depth_map_passes.h"

#include <vector>

namespace gs::depth_map {

// Whether the receiver triangle a, b, c (world; one that casts) compares its depth in the
// `side`-texel map of `frustum` (light `light`, the technique's `options`) lowered by more than
// two texels' widths at its centre's depth, along the light's ray: a triangle whose false light
// lowered_errors counts, and the walks beside feet (depth_map_contacts.h) leave to it.
bool lowered_past_texels(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c,
                         const LightFrustum &frustum, const SpotLight &light, int side,
                         const TechniqueOptions &options);

// Per scene object (zero for one that casts nothing), with the receiver that has the most: the
// pixels the `side << k`-texel map of `frustum` (light `light`, the technique's `options`;
// k = 0 .. 3) leaves lit on receiver triangles that cast, face the light and the camera, and
// are lowered past two texels' widths (lowered_past_texels, at the map's side), where that
// caster alone shadows them from this light, no other light's shadow holds them, and no pixel
// within one (Chebyshev) of them lies on the true shadow's boundary (FrameTruth,
// depth_map_frame_truth.h): the measure's interior false light.
std::vector<ContactError> lowered_errors(const Scene &scene, const std::vector<WorldMesh> &meshes,
                                         const LightFrustum &frustum, const SpotLight &light,
                                         int side, const TechniqueOptions &options);

}  // namespace gs::depth_map
