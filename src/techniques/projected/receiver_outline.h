// The outline of a receiver seen from a light, for draw_mask_surface's fins
// (receiver_mask_surface.cpp): the edges of its light-facing triangles that no other one shares,
// and those triangles on the light's screen, to tell whether anything of the receiver lies
// beyond an edge. World space and the light's size x size Glide screen (texels).
#pragma once

#include "techniques/light_passes/scene_pass.h"
#include "techniques/projected/projected_shadow.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gs {

// The receiver's outline from the light: the edges of its light-facing triangles that no other
// light-facing triangle shares (by world position), as pairs of position ids, sorted, so that a
// lookup is a search; and those triangles' corners in the light's screen (texels), to find what
// lies beyond an edge.
struct ReceiverOutline {
  struct Lit {
    glm::vec3 corner[3];  // world
    glm::vec2 screen[3];  // light screen, texels
    bool in_front;        // every corner before the light (else it is taken to overlap all)
    glm::vec2 low, high;  // box of `screen`; the whole plane unless in front and within kNear
  };
  // Light screen texels: within this of the view, float rounding in a separating-axis test
  // is below 1e-3 texel.
  static constexpr float kNear = 1e4f;
  // Per vertex of the receiver, an id equal to another vertex's exactly where their world
  // positions compare equal (as floats: 0 and -0 alike), so an edge is a pair of ids; ids run
  // from 0 up to id_count.
  std::vector<std::uint32_t> position_id;
  std::uint32_t id_count = 0;
  // The outline's edges filed under their lower id: its higher ids at higher[start[id]] up to
  // higher[start[id + 1]].
  std::vector<std::uint32_t> start, higher;
  std::vector<Lit> lit;
  // The lit triangles filed by the kCell x kCell texel cells their boxes meet, over the grid's
  // `columns` x `rows` cells from `origin` (light screen, texels; a box reaching past the grid
  // is filed under the border cells it is clamped to, as the queries are): cell c's at
  // in_cell[cell_start[c]] up to in_cell[cell_start[c + 1]]. Those boxed as the whole plane are
  // in `everywhere`. nothing_beyond looks only at the triangles of the cells its fin's box
  // meets, and the same tests then give the same answer. Filed at its first question (`filed`;
  // most masks ask none): `size` is the view's.
  static constexpr float kCell = 32.0f;
  int size = 0;
  mutable bool filed = false;
  mutable glm::vec2 origin{0.0f};
  mutable int columns = 0, rows = 0;
  mutable std::vector<std::uint32_t> cell_start, in_cell, everywhere;
  // Cells low..high (inclusive) of the texel box low..high, clamped to the grid.
  void cells_of(const glm::vec2 &low, const glm::vec2 &high, glm::ivec2 &first, glm::ivec2 &last) const {
    auto cell = [&](float v, float from, int count) {
      return static_cast<int>(std::clamp((v - from) / kCell, 0.0f, static_cast<float>(count - 1)));
    };
    first = {cell(low.x, origin.x, columns), cell(low.y, origin.y, rows)};
    last = {cell(high.x, origin.x, columns), cell(high.y, origin.y, rows)};
  }
  void file_lit_triangles() const {
    filed = true;
    // The view's square and as much again each side: the fins nothing_beyond is asked about lie
    // within about a texel of it or are clamped to its border with what lies there.
    origin = glm::vec2(-static_cast<float>(size));
    columns = rows = std::max(1, static_cast<int>(std::ceil(3.0f * static_cast<float>(size) / kCell)));
    cell_start.assign(static_cast<std::size_t>(columns * rows) + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {  // count, then file (a counting sort)
      std::vector<std::uint32_t> next;
      if (pass == 1) {
        for (std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
        next.assign(cell_start.begin(), cell_start.end() - 1);
        in_cell.resize(cell_start.back());
      }
      for (std::uint32_t i = 0; i < lit.size(); ++i) {
        const Lit &t = lit[i];
        if (!(std::isfinite(t.low.x) && std::isfinite(t.low.y) && std::isfinite(t.high.x) && std::isfinite(t.high.y))) {
          if (pass == 0) everywhere.push_back(i);
          continue;
        }
        glm::ivec2 first, last;
        cells_of(t.low, t.high, first, last);
        for (int y = first.y; y <= last.y; ++y)
          for (int x = first.x; x <= last.x; ++x) {
            const auto c = static_cast<std::size_t>(y * columns + x);
            if (pass == 0) ++cell_start[c + 1]; else in_cell[next[c]++] = i;
          }
      }
    }
  }
  std::uint64_t key(unsigned p, unsigned q) const {
    const std::uint64_t a = position_id[p], b = position_id[q];
    return a < b ? a << 32 | b : b << 32 | a;
  }
  // Whether the edge between vertices p and q of the receiver lies on the outline.
  bool contains(unsigned p, unsigned q) const {
    const std::uint64_t edge = key(p, q);
    const auto first = higher.begin() + start[edge >> 32], last = higher.begin() + start[(edge >> 32) + 1];
    return std::find(first, last, static_cast<std::uint32_t>(edge)) != last;
  }
  // Whether no light-facing triangle of the receiver but those with a corner at p or q (its
  // neighbours along the outline) overlaps the convex quad `fin` (texels; separating axes).
  bool nothing_beyond(const glm::vec3 &p, const glm::vec3 &q, const glm::vec2 (&fin)[4]) const {
    auto separated = [](const glm::vec2 *a, int na, const glm::vec2 *b, int nb) {
      for (int i = 0; i < na; ++i) {
        const glm::vec2 side = a[(i + 1) % na] - a[i];
        const glm::vec2 axis(side.y, -side.x);
        float a_low = INFINITY, a_high = -INFINITY, b_low = INFINITY, b_high = -INFINITY;
        for (int k = 0; k < na; ++k) a_low = std::min(a_low, glm::dot(axis, a[k])), a_high = std::max(a_high, glm::dot(axis, a[k]));
        for (int k = 0; k < nb; ++k) b_low = std::min(b_low, glm::dot(axis, b[k])), b_high = std::max(b_high, glm::dot(axis, b[k]));
        if (a_high <= b_low || b_high <= a_low) return true;
      }
      return false;
    };
    glm::vec2 low(INFINITY), high(-INFINITY);
    for (const glm::vec2 &corner : fin) low = glm::min(low, corner), high = glm::max(high, corner);
    auto beyond = [&](const Lit &t) {
      // Boxes more than a texel apart: the fin (a rectangle, whose right angles put one of the
      // two polygons' edge normals within 45 degrees of the direction between their nearest
      // points) and the triangle are separated by more than 0.7 texel along that normal, which
      // `separated` finds whatever the rounding; skipped before the tests below, as they would.
      if (t.high.x + 1.0f < low.x || high.x + 1.0f < t.low.x || t.high.y + 1.0f < low.y ||
          high.y + 1.0f < t.low.y) {
        return false;
      }
      bool neighbour = false;
      for (const glm::vec3 &corner : t.corner) neighbour = neighbour || corner == p || corner == q;
      if (neighbour) return false;
      if (!t.in_front) return true;
      return !separated(fin, 4, t.screen, 3) && !separated(t.screen, 3, fin, 4);
    };
    if (!filed) file_lit_triangles();
    for (const std::uint32_t i : everywhere)
      if (beyond(lit[i])) return false;
    // A triangle the box test keeps has its box within a texel of the fin's: within two, for
    // the rounding of the sums, lie the cells to look in. A NaN corner looks everywhere.
    glm::ivec2 first(0), last(columns - 1, rows - 1);
    if (std::isfinite(low.x) && std::isfinite(low.y) && std::isfinite(high.x) && std::isfinite(high.y)) {
      cells_of(low - 2.0f, high + 2.0f, first, last);
    }
    for (int y = first.y; y <= last.y; ++y)
      for (int x = first.x; x <= last.x; ++x) {
        const auto c = static_cast<std::size_t>(y * columns + x);
        for (std::uint32_t k = cell_start[c]; k < cell_start[c + 1]; ++k)
          if (beyond(lit[in_cell[k]])) return false;
      }
    return true;
  }
};

// The outline of `receiver`'s triangles facing the light of `view`, whose vertices in the light's
// clip space are `clip`.
ReceiverOutline outline_of(const LightView &view, const ProjectedObject &receiver,
                           const std::vector<glm::vec4> &clip);

}  // namespace gs
