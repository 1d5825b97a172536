// Internal to step 3 (receiver_coords.cpp): which receiver polygons can take the caster's shadow
// or its edge, from the cells of the shadow texture they reach (LightView's occupied, covered and
// silhouette cells). A polygon is given by its light clip coordinates, all with w > 0; the
// texture in light screen texels (x right, y down).
#pragma once

#include "techniques/projected/projected_shadow.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace gs {

// The box (light screen, texels) a receiver polygon spans: its projection is convex, so its
// corners bound it.
void texel_box(const LightView &view, const glm::vec4 *light_clip, std::size_t count,
               glm::vec2 &low, glm::vec2 &high);

// Whether a receiver polygon, given by its light clip coordinates (all with w > 0), can be in
// the caster's shadow: it must see an occupied cell of the texture (its projection is convex, so
// its bounding box bounds it; one texel of margin covers bilinear filtering's reach) and reach
// beyond the caster's nearest point in that cell.
bool sees_caster(const LightView &view, const glm::vec4 *light_clip, std::size_t count);

// Whether any of LightView::covered's cells lies within reach of a receiver polygon: the texel
// box its projection spans, widened by bilinear filtering's reach and the shim's snapping.
bool reaches_covered_cell(const LightView &view, const glm::vec4 *light_clip, std::size_t count);

// The pixel centres (Glide screen) that a flagged receiver triangle of `triangles` (step 3's,
// step-4 screen corners unsnapped) thinner than the Voodoo's 1/16-pixel snap (its least height
// under 1/16 px) holds where its texture coordinates reach a cell the caster covers, but that
// neither its snapped self nor a flagged triangle as thick as the snap draws. The snap hands
// such a centre to a thin neighbour, or one step 3 did not flag, whose (s, t) there extend
// its own far beyond where it lies (a floor seen 7 cm above it, planar19_camera_7cm_160x120:
// box0's whole shadow, 5 pixels, left lit), so whether the frame shadows it is unknown.
// `projective`: the divisor is tmuvtx[0].oow (else oow); centres on the width x height screen.
int centres_lost_to_snap(const LightView &view, const std::vector<ShadowTriangle> &triangles,
                         bool projective, int width, int height);

// LightView::silhouette by rows, as bits (cell x of a row at bit x % 64 of its word x / 64), so
// that a box's silhouette cells are bounded in a step or two per row: the first silhouette
// column at or after x and the last at or before it (kFineCells and -1 when there is none).
class SilhouetteRows {
 public:
  static constexpr int kSide = LightView::kFineCells;
  static_assert(kSide % 64 == 0, "whole words per row");
  explicit SilhouetteRows(const LightView &view) : bits_(static_cast<std::size_t>(kSide * kWords), 0) {
    for (int y = 0; y < kSide; ++y) {
      for (int x = 0; x < kSide; ++x) {
        if (view.silhouette[static_cast<std::size_t>(y * kSide + x)]) {
          bits_[static_cast<std::size_t>(y * kWords + x / 64)] |= std::uint64_t{1} << (x % 64);
        }
      }
    }
  }
  int next(int y, int x) const {  // 0 <= x < kSide
    const std::uint64_t *row = &bits_[static_cast<std::size_t>(y * kWords)];
    for (int word = x / 64; word < kWords; ++word) {
      const std::uint64_t from = word == x / 64 ? ~std::uint64_t{0} << (x % 64) : ~std::uint64_t{0};
      if (const std::uint64_t found = row[word] & from) return word * 64 + __builtin_ctzll(found);
    }
    return kSide;
  }
  int previous(int y, int x) const {  // 0 <= x < kSide
    const std::uint64_t *row = &bits_[static_cast<std::size_t>(y * kWords)];
    for (int word = x / 64; word >= 0; --word) {
      const std::uint64_t to = word == x / 64 ? ~std::uint64_t{0} >> (63 - x % 64) : ~std::uint64_t{0};
      if (const std::uint64_t found = row[word] & to) return word * 64 + 63 - __builtin_clzll(found);
    }
    return -1;
  }

 private:
  static constexpr int kWords = kSide / 64;
  std::vector<std::uint64_t> bits_;  // [row * kWords + word]
};

// The world-space planes of the rectangle (in the texture) around the silhouette's cells
// (LightView::silhouette: where the shadow's edge can lie; deep inside a shadow the texels' size
// moves no edge) that a receiver polygon, given by its light clip coordinates (all w > 0), can
// see: those within its texel box widened by bilinear filtering's reach, as in
// reaches_covered_cell. Outside it no shadow edge falls on the polygon. False when none.
bool edge_rectangle(const LightView &view, const SilhouetteRows &rows, const glm::vec4 *light_clip,
                    std::size_t count, const glm::mat4 &world_to_light_clip,
                    std::vector<glm::vec4> &planes);

}  // namespace gs
