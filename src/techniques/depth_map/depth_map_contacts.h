// Internal to the depth-map technique: the interior error along the lines where a caster meets a
// receiver (its foot: a box sunk in the floor, a ball round the light resting on it), which are
// no edge of the caster's silhouette from the light, so shadow_edge_error.h never sees them.
// There the shadow's edge lies at the foot itself, and the map moves it: the lookup's texels
// beside the foot read what lies in front of it (a texel on a receiver the light grazes spans a
// long stretch of it), and the biases carry the caster's depths back (slope term, facet push) and
// the receiver's forward (receiver-plane bias) past a gap between them that closes at the foot.
// The estimate replays the map's lookup on the receiver beside each foot. Spaces: world (meshes,
// planes); light clip and the map's texture coordinates (s, t, r, q; r/q the stored depth 0..1);
// screen pixels (footprint_screen_pixels).
#pragma once

#include "techniques/depth_map/depth_map_passes.h"
#include "techniques/texel_error/shadow_edge_error.h"

#include <cstddef>
#include <vector>

namespace gs::depth_map {

// One caster's estimate along its feet under one light, and the receiver with the most of it.
struct ContactError {
  EdgeErrorEstimate pixels;  // screen pixels, at the map's side and 2, 4 and 8 times it
  std::size_t receiver = 0;  // index into scene.objects
};

// Per scene object (zero for one that casts nothing or touches no receiver): the interior error
// the `side`-texel map of `frustum` (light `light`, the technique's `options`) makes beside the
// lines where the caster's triangles meet a receiving triangle that faces the light, on the parts
// of those receivers the camera sees. At each sample of a foot the receiver is walked away from
// it on both sides (straight across the foot, and along its triangle's longest edge where the
// straight walk leaves the triangle), and each point's shadow from that caster (a ray to the
// light) is compared with the lookup of a map that holds the caster and the receiver (when it
// casts) as step 1 draws them: its facet push, slope term and bounded copy, the receiver's
// lowered depth, the 2x2 percentage-closer lookup or the nearest texel. What is wrong beyond the
// excused pixels of the foot's edge on screen counts. The frame's mask is every light's shadow
// at once: a point another light's shadow holds is wrong for none, and false light beside a foot
// whose other side the frame has in shadow (another light's, another caster's) is next to no
// edge, so nothing of it is excused.
std::vector<ContactError> contact_errors(const Scene &scene, const std::vector<WorldMesh> &meshes,
                                         const LightFrustum &frustum, const SpotLight &light,
                                         int side, const TechniqueOptions &options);

}  // namespace gs::depth_map
