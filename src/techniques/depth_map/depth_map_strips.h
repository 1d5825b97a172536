// Internal to the depth-map technique: the interior error on a receiver seen as a thin strip (a
// floor from a few centimetres above it, a row or two of pixels). A shadow edge running nearly
// along such a strip crosses its pixel centres far from where a stray of a fraction of a texel
// across the edge puts it (the crossing moves by the stray over the sine of the angle between
// them), and the strip has no pixels across the edge to hold the band that shadow_edge_error.h
// excuses there: planar19_camera_5cm, crumple_loose's shadow edge moved 4 px along the floor's
// one row, 2 interior pixels against an estimate of 0. On such a strip the estimate replays the
// map's lookup (depth_map_replay.h) at the strip's own pixel centres and counts what the error
// measure would. Spaces: world (meshes, rays in double); camera clip and NDC; screen pixels (x
// right, rows from the top, as the measure's masks).
#pragma once

#include "techniques/depth_map/depth_map_contacts.h"
#include "techniques/depth_map/depth_map_passes.h"

#include <vector>

namespace gs::depth_map {

// Per scene object (zero for one that casts nothing), with the receiver that has the most: the
// pixels of every receiver whose triangles facing the camera make a strip under 3 px thick on
// screen (their screen area over their extent along the strip) that the lookup of the
// `side << k`-texel map of `frustum` (light `light`, the technique's `options`; k = 0 .. 3) gets
// wrong against a ray to the light,
// where that caster alone decides, and that lie more than a pixel (Chebyshev) from every pixel
// of the strip whose 4-neighbour on it the truth calls otherwise: the measure's interior error.
std::vector<ContactError> strip_errors(const Scene &scene,
                                        const std::vector<WorldMesh> &meshes,
                                        const LightFrustum &frustum, const SpotLight &light,
                                        int side, const TechniqueOptions &options);

}  // namespace gs::depth_map
