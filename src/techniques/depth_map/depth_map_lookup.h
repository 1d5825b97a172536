// Internal to the depth-map technique: the map coordinates a receiver triangle looks the map up
// with, each triangle's corners unshared, the depth it compares lowered by the triangle's own
// depth change across the lookup's reach (a receiver-plane bias). A lit surface reads, within
// the lookup's 2x2 of texels, samples of its own plane up to that change nearer than itself;
// lowering the receiver's depth instead of pushing the caster back leaves every caster where it
// is, so a face the light sees almost edge-on still shadows the floor close behind it. Only a
// receiver that casts takes it (depth_map_passes.h, draw_receiver): the map holds no depth of
// one that does not, and near a caster standing on it the bias would lift it past that caster's
// surface. Spaces: world (the corners); light texture (s, t, r, q: s/q, t/q in 0..1 across the
// map, r/q the map's depth 0..1, q the light-view depth).
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace gs::depth_map {

// `corners`: three world positions per triangle. `to_map`: world to light texture coordinates.
// `side`: the map's side in texels. `factor`: the share of the triangle's depth change over one
// texel along each map axis (|dr/dx| + |dr/dy|, r/q per texel) taken off r/q, never more than
// the triangle's own span of r/q over its part inside the map; 0: none. A triangle reaching
// behind the light's plane (q <= 0 at a corner) gets it too, from its homogeneous corners (where
// q <= 0 the q gate decides).
std::vector<glm::vec4> biased_map_coords(const std::vector<glm::vec3> &corners,
                                         const glm::mat4 &to_map, int side, float factor);

}  // namespace gs::depth_map
