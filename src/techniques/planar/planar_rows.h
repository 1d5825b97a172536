// Internal to the planar technique's step 3 (planar_shadow.cpp): a shadow polygon's pixels as
// the rows of pixel centres it holds. Space: Glide screen (pixels, y down; a pixel's centre at
// half-integer x and y, the grid the 12.4 snap keeps exactly).
//
// Why rows: the Voodoo snaps every vertex to 1/16 px, which moves an edge by up to 1/32 px
// across itself. Across a steep edge that is at most a sixteenth of a pixel along a row, but an
// edge at slope s (dy/dx) moves along the row by 1/32 px over s: on a floor seen from a camera
// 10 cm above it, 9 m away, every shadow edge on the floor is nearly level on screen (the floor
// is squeezed to 1% of its width) and a box's shadow 0.3 px tall ran along the centres of its
// row within 0.03 px (/work/aud18 near-camera-behind_18652: the snap left 8 of its 14 pixels
// lit, on the floor's top row against the sky, where no neighbour shows they lie by an edge:
// 0.150% of the receiver pixels as interior). So step 3 finds, row by row, the pixels whose
// centres the polygon holds (its exact crossings of the row's centre line) and draws each row's
// run as a rectangle on pixel boundaries, which the snap leaves where it is.
// The receiver triangle was snapped too, and at such angles the pixels it drew are not those
// whose centres it holds: a centre a hair inside one floor triangle was drawn by the next, whose
// depth the first one's cover failed. So the run is also cut to the pixels the triangle drew (its
// snapped corners' crossings, ties included: a tie lies on an edge both triangles share, where
// their depths agree), and step 1 casts each polygon on the triangle with its edges moved out by
// what a sixteenth of a pixel spans there (planar_casting.cpp), so the pixels it drew beyond its
// exact edges get the shadow that falls on its plane there.
// Neighbouring polygons compute a shared edge's crossing from the same end, so their runs meet
// (or overlap by the pixel whose centre lies on it, which the seals darken once).
#pragma once

#include <glide.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace gs::planar {

// The centres of row `row` (y = row + 0.5) from x = left to x = right, unsnapped.
struct RowSpan {
  int row = 0;
  double left = INFINITY, right = -INFINITY;
};

// The rows of pixel centres the convex `polygon` (Glide screen, unsnapped) holds within rows
// 0 to `height` - 1, each with where its edges cross that row's centre line.
inline void row_spans(const std::vector<GrVertex> &polygon, int height,
                      std::vector<RowSpan> &spans) {
  spans.clear();
  if (polygon.size() < 3) return;
  float low = INFINITY, high = -INFINITY;
  for (const GrVertex &v : polygon) low = std::min(low, v.y), high = std::max(high, v.y);
  // Rows whose centre line y = row + 0.5 lies within [low, high].
  const int first = std::max(0, static_cast<int>(std::ceil(static_cast<double>(low) - 0.5)));
  const int last =
      std::min(height - 1, static_cast<int>(std::floor(static_cast<double>(high) - 0.5)));
  if (first > last) return;
  spans.resize(static_cast<std::size_t>(last - first + 1));
  for (int row = first; row <= last; ++row) spans[static_cast<std::size_t>(row - first)].row = row;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const GrVertex &a = polygon[i], &b = polygon[(i + 1) % n];
    // From the upper end (then the left one), whichever way the edge is walked, so that the
    // polygon on its other side finds the same crossings.
    const bool forward = a.y < b.y || (a.y == b.y && a.x < b.x);
    const GrVertex &p = forward ? a : b, &q = forward ? b : a;
    const int from = std::max(first, static_cast<int>(std::ceil(static_cast<double>(p.y) - 0.5)));
    const int to = std::min(last, static_cast<int>(std::floor(static_cast<double>(q.y) - 0.5)));
    for (int row = from; row <= to; ++row) {
      RowSpan &span = spans[static_cast<std::size_t>(row - first)];
      const double y = row + 0.5;
      if (q.y == p.y) {  // level with the row: both ends lie on it
        span.left = std::min({span.left, static_cast<double>(p.x), static_cast<double>(q.x)});
        span.right = std::max({span.right, static_cast<double>(p.x), static_cast<double>(q.x)});
        continue;
      }
      const double x = p.x + (static_cast<double>(q.x) - p.x) * ((y - p.y) / (q.y - p.y));
      span.left = std::min(span.left, x);
      span.right = std::max(span.right, x);
    }
  }
}

}  // namespace gs::planar
