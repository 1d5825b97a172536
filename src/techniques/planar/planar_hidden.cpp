// The planar technique's hidden regions: where a caster passes through a receiver's plane, the
// part of the plane its surface hides from the camera, which the shadow polygons leave out
// (planar_pieces.h). World space throughout.
#include "techniques/planar/planar_pieces.h"

#include <algorithm>

namespace gs::planar {
namespace {

// The region `seen` (counter-clockwise from the camera) hides on `receiver`'s plane, or false if
// it does not pass through that plane or hides nothing of the receiver triangle. `camera_height`
// is the camera's height above the plane (> 0); `pixel` the tangent of a pixel's angle.
bool hidden_region(const CasterTriangle &seen, const ReceiverTriangle &receiver,
                   const CameraCut &camera_cut, float camera_height, float pixel,
                   SmallPolygon &polygon, SmallPolygon &scratch, HiddenRegion &region) {
  const glm::vec3 &camera = camera_cut.position;
  float low = INFINITY, high = -INFINITY;
  for (const glm::vec3 &corner : seen.corner) {
    const float h = glm::dot(receiver.normal, corner) - receiver.offset;
    low = std::min(low, h), high = std::max(high, h);
  }
  if (!(low < 0.0f && high > 0.0f)) return false;
  polygon.n = 3;
  std::copy(seen.corner.begin(), seen.corner.end(), polygon.v.begin());
  clip_keep(polygon, receiver.normal, receiver.offset, scratch);
  // Only below the camera: a point level with it or above would hide the plane out to infinity.
  const float top = camera_height * kNearLightHeight;
  if (high > top) clip_keep(polygon, -receiver.normal, -(receiver.offset + top), scratch);
  // Only beyond the camera's near plane: the scene pass clipped away what is nearer, so it hides
  // nothing (tests/hard_cases/audit/sv18_near_plane_in_hut_post_through_roof: the hut's wall
  // 0.15 m from the camera, cut away by the 0.3 m near plane, hid the post's sides seen through
  // it, which were left lit: 4.5% of the receiver pixels).
  if (polygon.n >= 3) {
    clip_keep(polygon, camera_cut.forward, camera_cut.near_offset, scratch);
  }
  if (polygon.n < 3 || polygon.n > region.normal.size()) return false;
  for (std::size_t i = 0; i < polygon.n; ++i) {
    const float d = glm::dot(receiver.normal, polygon.v[i]) - receiver.offset;
    polygon.v[i] = camera + (polygon.v[i] - camera) * (camera_height / (camera_height - d));
  }
  region.n = 0;
  for (std::size_t i = 0; i < polygon.n; ++i) {
    const glm::vec3 &from = polygon.v[i], &to = polygon.v[(i + 1) % polygon.n];
    const glm::vec3 inward = glm::cross(receiver.normal, to - from);
    const float length = glm::length(inward);
    if (!(length > 1e-9f)) continue;
    region.normal[region.n] = inward / length;
    region.offset[region.n] = glm::dot(region.normal[region.n], from);
    region.overlap[region.n] =
        pixel * std::max(glm::distance(camera, from), glm::distance(camera, to));
    ++region.n;
  }
  if (region.n < 3) return false;
  // Nothing of the receiver triangle inside: no need to cut its polygons.
  for (std::size_t e = 0; e < region.n; ++e) {
    bool outside = true;
    for (const glm::vec3 &corner : receiver.corner) {
      outside = outside && glm::dot(region.normal[e], corner) <= region.offset[e];
    }
    if (outside) return false;
  }
  return true;
}

}  // namespace

// `pieces` less `region`: each piece that overlaps it is replaced by its parts outside the
// region's edges in turn, part e also inside edges 0 to e-1 so that the parts do not pile up
// over later regions. Those inner edges are moved out by `overlap` (a pixel), so neighbouring
// parts overlap instead of leaving cracks where their vertices round differently; the covers'
// depth levels darken an overlapped pixel once all the same. A part that would need more corners
// than a SmallPolygon holds is left whole (the margin of before, never less shadow).
void subtract_hidden(std::vector<SmallPolygon> &pieces, const HiddenRegion &region,
                     std::vector<SmallPolygon> &kept, SmallPolygon &scratch) {
  kept.clear();
  for (const SmallPolygon &piece : pieces) {
    bool apart = false;
    for (std::size_t e = 0; e < region.n && !apart; ++e) {
      apart = true;
      for (std::size_t i = 0; i < piece.n && apart; ++i) {
        apart = glm::dot(region.normal[e], piece.v[i]) <= region.offset[e];
      }
    }
    if (apart || piece.n + region.n > piece.v.size()) {
      kept.push_back(piece);
      continue;
    }
    for (std::size_t e = 0; e < region.n; ++e) {
      SmallPolygon part = piece;
      clip_keep(part, -region.normal[e], -region.offset[e], scratch);
      for (std::size_t f = 0; f < e && part.n >= 3; ++f) {
        clip_keep(part, region.normal[f], region.offset[f] - region.overlap[f], scratch);
      }
      if (part.n >= 3) kept.push_back(part);
    }
  }
  std::swap(pieces, kept);
}

void hidden_regions(const PlanarCaster &caster, const ReceiverTriangle &r,
                    const CameraCut &camera, float pixel, std::vector<HiddenRegion> &hidden,
                    SmallPolygon &polygon, SmallPolygon &scratch) {
  hidden.clear();
  const float camera_height = glm::dot(r.normal, camera.position) - r.offset;
  if (!(camera_height > 0.0f)) return;
  HiddenRegion region;
  for (const CasterTriangle &seen : caster.seen) {
    if (!seen.box.overlaps(r.box)) continue;
    if (hidden_region(seen, r, camera, camera_height, pixel, polygon, scratch, region)) {
      hidden.push_back(region);
    }
  }
}

}  // namespace gs::planar
