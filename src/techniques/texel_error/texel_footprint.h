// How many screen pixels one texel of a projected shadow texture spans on a receiver, across
// the direction the texel is stretched in, where the caster's shadow edge can fall on it (near
// the caster's silhouette in the texture), and a whole shadow's footprint: the largest over all
// but a sliver of the screen. The projected technique refuses a shadow whose texels are too
// coarse (its edge would stray more than a pixel from the true one): docs/hard_cases_results.md ("Shadow
// texels against screen pixels") has the threshold and its measurement.
#pragma once

#include "techniques/geometry/projection.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace gs {

// Footprints above this many pixels are refused by default, measured with `hard_case_sweeps
// footprint` (interior error against the footprint, docs/hard_cases_results.md): bilinear filtering puts
// an edge within about half a texel of the caster's, point sampling (the chroma-key variant,
// --point) within a texel, so it gets a smaller limit.
inline constexpr float kLargestTexelFootprintPx = 5.0f;
inline constexpr float kLargestPointSampledFootprintPx = 3.0f;
// The screen share a shadow's footprint may leave out: the polygons where the texels are
// coarsest (a facet the light grazes stretches a texel over the whole facet) are skipped until
// they cover this much of the screen. Half the 0.1% interior-error budget: even if every one of
// those pixels were wrong, the frame would stay within it.
inline constexpr float kFootprintIgnoredScreenShare = 0.0005f;

// How far a filtered lookup reads around its sample, texels: bilinear filtering (and the depth
// map's percentage-closer lookup) weighs the 2x2 texels whose centres lie within one texel of
// it; half a texel more for rounding. Where a shadow edge can fall is within this of the
// caster's silhouette in the texture.
inline constexpr float kFilterReachTexels = 1.5f;

// The two projections the footprint compares, and where a shadow can fall.
struct FootprintSpace {
  glm::mat4 light_clip{1.0f};   // world to the shadow texture's light clip space
  float texels = 256.0f;        // the texture's side: light NDC [-1, 1] spans this many texels
  glm::mat4 camera_clip{1.0f};  // world to camera clip space
  glm::vec2 pixels{1.0f};       // the screen: camera NDC [-1, 1] spans this many pixels
  // World-space planes (kept where dot(plane, (p, 1)) >= 0) bounding the region the caster's
  // shadow can reach: beyond its front, inside the camera's view.
  std::vector<glm::vec4> planes;
};

// Unit tangents t1, t2 (world space) of a plane with unit normal `normal`: the basis both
// projections are differentiated along on a receiver's plane.
void plane_tangents(const glm::vec3 &normal, glm::vec3 &t1, glm::vec3 &t2);

// A projection's NDC x, y at world point p differentiated along a plane's tangents t1, t2
// (world, unit), scaled by half the extent [-1, 1] spans (texels or pixels): texels or pixels
// per metre on the plane, a 2x2 Jacobian (column-major: column k along t(k+1)).
glm::mat2 tangent_jacobian(const glm::mat4 &clip_from_world, const glm::vec3 &p,
                           const glm::vec2 &extent, const glm::vec3 &t1, const glm::vec3 &t2);

// The screen position (pixels from the screen's centre, y up) of a world point before the
// camera (camera clip w > 0).
glm::vec2 footprint_screen_pixels(const FootprintSpace &space, const glm::vec3 &world);

// The area of a simple polygon (any units squared) from its corners in order (shoelace).
float polygon_area(const std::vector<glm::vec2> &polygon);

// One receiver polygon's part where the shadow can fall: its largest footprint (screen pixels a
// texel spans across the direction it is stretched in, texel_footprint.cpp) and its area on
// screen (pixels).
struct FootprintSample {
  float pixels_per_texel = 0.0f;
  float screen_area = 0.0f;
  std::size_t receiver = 0;  // index into scene.objects
};

// The sample of the convex planar polygon `world` (world space, unit normal `normal`), clipped
// to `planes` (world space: space.planes and the polygon's own bounds): the stretch is
// evaluated at the clipped polygon's corners (both mappings are projective on the polygon's
// plane, and their stretch grows towards the side where the camera is nearer relative to the
// light, so the largest lies at a corner). A zero sample when nothing is left.
FootprintSample texel_footprint(const FootprintSpace &space, const glm::vec3 &normal,
                                const std::vector<glm::vec4> &planes,
                                std::vector<ClipVertex> &world, std::vector<ClipVertex> &scratch);

// The footprint of a whole shadow: the largest sample's once the largest ones, together
// covering at most `ignored_pixels` of the screen, are left out (the sample returned names the
// receiver). A zero sample when there is none.
FootprintSample shadow_footprint(std::vector<FootprintSample> samples, float ignored_pixels);

// How a refusal ends, after "; " or ", so ": the caster it names gets no shadow from the light
// it names. Every refusal of these estimates' (texel_footprint_error, shadow_edge_error.h) and
// the projected technique's step 1 (light_view_fit.cpp) says it in these words.
constexpr const char *kCastsNoShadow = "it casts no shadow from this light";

// The refusal of a shadow whose texels are too coarse for the screen (the projected techniques'
// and the depth map's), naming the light, the caster, the receiver, the footprint and the
// largest accepted, ending with `accepted_words` (accepted_size_words, shadow_edge_error.h: the
// size that would be accepted, along the shadow's edges too) and kCastsNoShadow. The reason
// is the refusal without that end ("; " and kCastsNoShadow), for a note that the shadow was
// drawn after all (ProjectedShadowOptions::grow_to_accepted).
std::string texel_footprint_error(const Scene &scene, std::size_t light, std::size_t caster,
                                  std::size_t receiver, float footprint, float largest, int size,
                                  const std::string &accepted_words);
std::string texel_footprint_reason(const Scene &scene, std::size_t light, std::size_t caster,
                                   std::size_t receiver, float footprint, float largest, int size,
                                   const std::string &accepted_words);

}  // namespace gs
