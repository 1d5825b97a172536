// The interior error a projected shadow texture's texels can make along its edges, per edge of
// the caster's silhouette from the light: where each edge's shadow lands on a receiver polygon,
// its length on screen times how far beyond the pixels next to it (which the error measure
// counts as the edge's band, not interior error) the texels move it across itself. The
// projected technique refuses a shadow whose estimate exceeds 0.1% of the receivers' pixels (with
// texel_footprint.h's check, which it complements: docs/hard_cases_results.md, "Shadow texels
// against screen pixels").
#pragma once

#include "techniques/geometry/projection.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/texel_error/texel_footprint.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gs {

// An edge of the caster's silhouette from the light (or its cut by a pierced receiver's plane),
// world space, as much of it as step 1 draws; the normal (world, not unit) of the caster's face
// along it that the light sees, and a point of that face off the edge (the texture covers its
// side of the edge). A cut has a zero normal: neither is known there. `rim`: the edge is on one
// triangle only (an open caster's border, mark_rims): no back of the caster hides what is behind.
struct SilhouetteSegment {
  glm::vec3 a{0.0f}, b{0.0f};
  glm::vec3 lit_face{0.0f};
  glm::vec3 face_point{0.0f};
  bool rim = false;
};

// The share of the receivers' pixels a frame's estimate may reach: the 0.1% interior-error
// budget, as the estimate is near the error measured against the truth
// (docs/hard_cases_results.md).
inline constexpr float kEdgeErrorReceiverShare = 0.001f;

// The budget's base: the screen pixels (Glide screen) whose centre some object's camera-facing
// triangle covers (the parts before the camera), each once, both as it is and as the Voodoo
// draws it (its corners snapped to 1/16 px). It is the error measure's base
// (src/measure/speed_error.cpp: every visible surface's pixels, caster or receiver, that the
// frame draws too) but for the pixels an object shadows on itself alone, which the measure
// leaves out and a technique cannot know without the truth's own rays (31 of the crumpled
// sheet's 301 pixels in planar19_camera_7cm_160x120). Summing the receivers' areas instead
// counted the floor behind a wall twice and made the budget up to a fifth larger than the
// measure's 0.1% (grazing_12217: 14,205 against 12,826 pixels, issue 14).
float receiver_screen_pixels(const Scene &scene, const FrameGeometry &frame);
// A lower bound of it for less work: the same pixels of the triangles wholly before the camera
// and in the guard band with a screen area of at least `least_area` pixels (> 0: the floors and
// walls, not a figure's many small ones), in the scene's order until `enough` are covered. A
// frame whose shadows' estimates fit 0.1% of it fits the budget.
float receiver_screen_pixels_at_least(const Scene &scene, const FrameGeometry &frame,
                                      float least_area, float enough);

// The frame's budget for the estimate (screen pixels): 0.1% of receiver_screen_pixels, in
// whole pixels, as a pixel centre is wrong or not. Under 1,000 pixels it is 0: any stray the
// estimate sees could put a whole pixel, over 0.1%, on the wrong side of an edge (a floor seen
// 10 cm above it, planar19_camera_10cm_160x120: an estimate of 0.034 px and one pixel wrong).
float edge_error_budget(const Scene &scene, const FrameGeometry &frame);

// Estimated interior error (wrong pixels beyond an edge's band), for the texture as it is and at
// 2, 4 and 8 times its side (the texels halve with each doubling), so that a refusal can name
// the size that would be accepted.
struct EdgeErrorEstimate {
  static constexpr int kSizes = 4;
  float pixels[kSizes] = {};
  void add(const EdgeErrorEstimate &other) {
    for (int k = 0; k < kSizes; ++k) pixels[k] += other.pixels[k];
  }
};

class SurfaceCuts;  // surface_cuts.h

// How the mask reads the texture where a shadow edge falls: the Voodoo 1's bilinear filter
// (4-bit fractions), a bilinear filter with fine fractions (the depth map's percentage-closer
// lookup over its 2x2 comparisons), or the nearest texel.
enum class EdgeLookup { kVoodooBilinear, kBilinear, kNearest };

// Adds to `estimate` the error along the shadows that `segments[candidates]` throw from
// `light_position` (world) onto the convex planar receiver polygon `polygon` (world positions,
// its unit normal `normal` facing the light, already clipped to where the shadow's edge can
// fall: texel_footprint). Along each shadow edge the texture's edge (where the filtered alpha
// is half, read by `lookup`; the Voodoo's filter needs more than half) is found from the texel
// centres the caster covers next to it, and its distance from the true edge measured across
// the edge on the screen, where the light's projection puts it on the plane (not through the
// projection's derivative at the true edge, which a grazed plane's texels outgrow within a
// texel). Only what the screen shows counts: a side of `polygon` along the screen's side (where
// the caller clipped it to the screen) is no border of the receiver, so a shadow edge is followed
// past it as far as its texture's edge can stray back onto the screen, and no band excuses the
// pixels next to the part of a true edge off the screen (stray_on_screen.h).
// A shadow edge where the caster touches the receiver lies under the caster, where no true
// edge is seen to excuse the pixel next to it: there every pixel the texture's edge strays out
// from under the caster counts where the camera (world) sees past the caster's lit face. Seen
// from behind its lit face, such an edge on a rim (a wall with no back, the foot of an open
// tube) shows the receiver beyond it, in the caster's shadow right from the foot: there the
// texture's edge straying under the caster lights it, beyond the band of the visible edge.
// A true edge that the caster's lit face along it hides from the camera (a light on the
// camera's side throws the edge behind the caster) has no band seen either: there what the
// texture's edge strays out from under the caster counts unless it ends behind that face too.
// With `cuts` (a texture masked by the receiver's surface), the caster's cut through the
// polygon is such a contact edge too, but where a kept contact strip holds its covered side.
void add_shadow_edge_error(const FootprintSpace &space, const glm::vec3 &light_position,
                           const glm::vec3 &camera_position, const glm::vec3 &normal,
                           const std::vector<ClipVertex> &polygon,
                           const std::vector<SilhouetteSegment> &segments,
                           const std::vector<std::size_t> &candidates, EdgeLookup lookup,
                           EdgeErrorEstimate &estimate, const SurfaceCuts *cuts = nullptr);
// The projected techniques' texture: the Voodoo 1's bilinear filter, or the nearest texel.
inline void add_shadow_edge_error(const FootprintSpace &space, const glm::vec3 &light_position,
                                  const glm::vec3 &camera_position, const glm::vec3 &normal,
                                  const std::vector<ClipVertex> &polygon,
                                  const std::vector<SilhouetteSegment> &segments,
                                  const std::vector<std::size_t> &candidates, bool bilinear,
                                  EdgeErrorEstimate &estimate, const SurfaceCuts *cuts = nullptr) {
  add_shadow_edge_error(space, light_position, camera_position, normal, polygon, segments,
                        candidates, bilinear ? EdgeLookup::kVoodooBilinear : EdgeLookup::kNearest,
                        estimate, cuts);
}

// Gives the cuts among `segments` (a zero lit_face: the caster cut by a pierced receiver's
// plane, one of `cut_planes`, world, positive on the light's side) the caster's triangle they
// lie on when it faces the light by its winding: its normal as lit_face, and a point of its part
// on the light's side as face_point. The light then sees that face standing on the receiver and
// the receiver before its foot is lit, as is the face: on screen no shadow edge runs between
// them to excuse the pixels next to the cut, so the cut is a contact edge (a box sunk in the
// floor under a light 0.2 m up, issue 14). Cuts on faces turned away stay as they are.
void complete_cuts(const SceneObject &caster, const glm::vec3 &light_position,
                   const std::vector<glm::vec4> &cut_planes, std::vector<SilhouetteSegment> &segments);

// Sets `rim` on the segments among `segments` (world) that lie along one of `rims` (world): the
// caster's edges that only one triangle has, its positions welded (LightView::rims, found with
// its silhouette in step 1): an open tube's or a sheet's border.
void mark_rims(const std::vector<std::pair<glm::vec3, glm::vec3>> &rims,
               std::vector<SilhouetteSegment> &segments);

// The smallest shadow size from `size` up to `largest_size`, doubling, at which a caster's
// shadow would be accepted: its coarsest texel footprint (`footprint` screen pixels at `size`,
// halving as the size doubles) at most `largest_footprint`, and, when `largest_edge_pixels` is
// set, the frame's edge error with it (`within_budget`) at most that. The edge error is
// estimated up to 8 times `size`; past that, it is extrapolated from there, halving with each
// doubling as the texels' width does (a guess: rendering at the size named may be refused again).
struct AcceptedSize {
  int size = 0;          // 0: none of the sizes tried
  int largest_tried = 0;
};
AcceptedSize smallest_accepted_size(int size, int largest_size, float footprint,
                                    float largest_footprint, const EdgeErrorEstimate &within_budget,
                                    const std::optional<float> &largest_edge_pixels);

// "size N would be accepted", or "no size up to M would be accepted": how refusals end.
std::string accepted_size_words(const AcceptedSize &accepted);

// The refusal of a shadow whose edges would stray too far (the projected techniques' and the
// depth map's), naming the light, the caster, the receiver with the most of the error, the
// estimate (`frame`: the frame's with this shadow's, `taken` of it by the shadows before)
// against the most accepted (pixels), and the size that would be accepted, ending with
// kCastsNoShadow (texel_footprint.h); the reason is the refusal without that end.
std::string shadow_edge_error_message(const Scene &scene, std::size_t light, std::size_t caster,
                                      std::size_t receiver, float taken,
                                      const EdgeErrorEstimate &frame, float largest_pixels,
                                      int size, const AcceptedSize &accepted);
std::string shadow_edge_error_reason(const Scene &scene, std::size_t light, std::size_t caster,
                                     std::size_t receiver, float taken,
                                     const EdgeErrorEstimate &frame, float largest_pixels,
                                     int size, const AcceptedSize &accepted);

// The refusal's reason (without kCastsNoShadow) for a shadow whose receiver triangles thinner
// than the Voodoo's 1/16-pixel snap lose `lost` pixel centres near the caster's texels to
// their neighbours (receiver_cells.h, centres_lost_to_snap): each may be wrong, over the
// frame's `largest_pixels` (edge_error_budget) with the `taken` of its other shadows.
std::string snapped_receivers_reason(const Scene &scene, std::size_t light, std::size_t caster,
                                     int lost, float taken, float largest_pixels);

}  // namespace gs
