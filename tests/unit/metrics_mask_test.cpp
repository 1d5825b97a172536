// The mask error metrics on synthetic masks built here: band against interior errors, distances
// to the true boundary, receivers, fractions, and the distance transform against brute force.
// The image comparisons and mask files: metrics_image_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "measure/metrics.h"

namespace {

using namespace gs;

struct Mask {
  int width, height;
  std::vector<std::uint8_t> pixels;
  Mask(int w, int h, std::uint8_t value = 0) : width(w), height(h), pixels(std::size_t(w) * h, value) {}
  void fill(int x0, int y0, int x1, int y1, std::uint8_t value) {  // [x0, x1) × [y0, y1)
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) pixels[std::size_t(y) * width + x] = value;
  }
};

MaskErrors compare(const Mask &technique, const Mask &truth, const Mask &receivers) {
  return compare_masks(technique.pixels, truth.pixels, receivers.pixels, truth.width, truth.height);
}

MaskErrors compare(const Mask &technique, const Mask &truth) {
  return compare(technique, truth, Mask(truth.width, truth.height, 1));
}

double interior(const MaskErrors &e) { return e.false_shadow_interior + e.false_light_interior; }

TEST(CompareMasks, IdenticalMasksHaveNoError) {
  Mask truth(64, 48);
  truth.fill(10, 10, 30, 30, 1);
  const MaskErrors e = compare(truth, truth);
  EXPECT_EQ(e.receiver_pixels, 64 * 48);
  EXPECT_EQ(e.false_shadow, 0);
  EXPECT_EQ(e.false_light, 0);
  EXPECT_EQ(e.misclassified, 0.0);
  EXPECT_EQ(e.max_distance_px, 0.0);
}

// Both sides of a shadow edge are boundary pixels, so a sideways shift by one leaves every wrong
// pixel on the boundary (distance 0); a diagonal shift puts one corner pixel a pixel away.
TEST(CompareMasks, OnePixelShiftIsBandErrorOnly) {
  Mask truth(64, 48), sideways(64, 48), diagonal(64, 48);
  truth.fill(10, 10, 30, 30, 1);
  sideways.fill(11, 10, 31, 30, 1);
  diagonal.fill(11, 11, 31, 31, 1);

  const MaskErrors s = compare(sideways, truth);
  EXPECT_EQ(s.false_shadow, 20);
  EXPECT_EQ(s.false_light, 20);
  EXPECT_DOUBLE_EQ(s.false_shadow_band, 20.0 / (64 * 48));
  EXPECT_DOUBLE_EQ(s.false_light_band, 20.0 / (64 * 48));
  EXPECT_EQ(interior(s), 0.0);
  EXPECT_LE(s.max_distance_px, 1.0);

  const MaskErrors d = compare(diagonal, truth);
  EXPECT_EQ(d.false_shadow, 39);
  EXPECT_EQ(d.false_light, 39);
  EXPECT_EQ(interior(d), 0.0);
  EXPECT_DOUBLE_EQ(d.max_distance_px, 1.0);  // corner (30,30) to boundary (30,29)
}

// The band is the 8-neighbourhood of the boundary: a wrong pixel diagonal to a boundary pixel is
// in it, one two pixels straight out is not.
TEST(CompareMasks, BandIsChebyshevDistanceOne) {
  Mask truth(40, 40), technique(40, 40);
  truth.fill(20, 20, 21, 21, 1);  // boundary: (20,20) and its four neighbours
  technique = truth;
  technique.fill(22, 21, 23, 22, 1);  // diagonal to (21,20)
  technique.fill(23, 20, 24, 21, 1);  // two pixels right of (21,20)
  const MaskErrors e = compare(technique, truth);
  EXPECT_DOUBLE_EQ(e.false_shadow_band, 1.0 / (40 * 40));
  EXPECT_DOUBLE_EQ(e.false_shadow_interior, 1.0 / (40 * 40));
  EXPECT_DOUBLE_EQ(e.max_distance_px, 2.0);
}

TEST(CompareMasks, HoleInLargeShadowIsInteriorFalseLight) {
  Mask truth(200, 200), technique(200, 200);
  truth.fill(20, 20, 180, 180, 1);
  technique.fill(20, 20, 180, 180, 1);
  technique.fill(98, 98, 103, 103, 0);
  const MaskErrors e = compare(technique, truth);
  EXPECT_EQ(e.false_light, 25);
  EXPECT_EQ(e.false_shadow, 0);
  EXPECT_DOUBLE_EQ(e.false_light_interior, 25.0 / (200 * 200));
  EXPECT_EQ(e.false_light_band, 0.0);
  // Inner boundary rows/columns are 20 and 179; the hole pixel (99..100, 99..100) deepest inside
  // is min(99 − 20, 179 − 100) = 79 from the nearest.
  EXPECT_DOUBLE_EQ(e.max_distance_px, 79.0);
}

TEST(CompareMasks, SpuriousBlobIsInteriorFalseShadowWithItsDistance) {
  Mask truth(200, 200), technique(200, 200);
  truth.fill(10, 10, 30, 30, 1);
  technique.fill(10, 10, 30, 30, 1);
  technique.fill(150, 100, 155, 105, 1);
  const MaskErrors e = compare(technique, truth);
  EXPECT_EQ(e.false_shadow, 25);
  EXPECT_EQ(e.false_light, 0);
  EXPECT_DOUBLE_EQ(e.false_shadow_interior, 25.0 / (200 * 200));
  EXPECT_EQ(e.false_shadow_band, 0.0);
  // Farthest blob pixel (154,104); nearest boundary pixel is the lit (30,29) beside the shadow.
  EXPECT_NEAR(e.max_distance_px, std::hypot(124.0, 75.0), 1e-9);
}

TEST(CompareMasks, NonReceiverPixelsAreIgnored) {
  Mask truth(40, 30), technique(40, 30), receivers(40, 30, 1);
  truth.fill(5, 5, 15, 15, 1);
  technique.fill(5, 5, 15, 15, 1);
  technique.fill(25, 5, 35, 15, 1);  // wrong, but on a non-receiver
  truth.fill(25, 20, 35, 25, 1);     // wrong too, same
  receivers.fill(20, 0, 40, 30, 0);
  const MaskErrors e = compare(technique, truth, receivers);
  EXPECT_EQ(e.receiver_pixels, 20 * 30);
  EXPECT_EQ(e.false_shadow, 0);
  EXPECT_EQ(e.false_light, 0);
  EXPECT_EQ(e.max_distance_px, 0.0);

  EXPECT_EQ(compare(technique, truth, Mask(40, 30, 0)).misclassified, 0.0);  // no NaN
}

// A receiver edge against non-receivers is a silhouette, not a shadow boundary: with no shadow
// edge anywhere a wrong pixel is interior and reported at the image diagonal.
TEST(CompareMasks, NoTrueBoundaryReportsImageDiagonal) {
  Mask truth(40, 30), technique(40, 30), receivers(40, 30, 1);
  truth.fill(0, 0, 20, 30, 1);
  receivers.fill(20, 0, 40, 30, 0);
  technique.fill(0, 0, 20, 30, 1);
  technique.fill(3, 3, 4, 4, 0);
  const MaskErrors e = compare(technique, truth, receivers);
  EXPECT_EQ(e.false_light, 1);
  EXPECT_DOUBLE_EQ(e.false_light_interior, 1.0 / (20 * 30));
  EXPECT_DOUBLE_EQ(e.max_distance_px, 50.0);
}

// An object's shadow on itself is left out of the count, but its edge is a true shadow edge: a
// lit receiver pixel beside an uncounted shadowed pixel is boundary, so a technique that draws
// that self-shadow a pixel wide of the truth makes band errors, not interior ones. Without the
// uncounted shadow the same pixels are interior, as are pixels two away with it.
TEST(CompareMasks, EdgeOfAnUncountedShadowIsABoundary) {
  Mask truth(40, 30), technique(40, 30), receivers(40, 30, 1), self_shadow(40, 30);
  self_shadow.fill(0, 0, 20, 30, 1);  // the left half: only its own object shadows it
  receivers.fill(0, 0, 20, 30, 0);
  technique.fill(0, 0, 22, 30, 1);    // the self-shadow drawn two columns too wide
  const MaskErrors with_edge = compare_masks(technique.pixels, truth.pixels, receivers.pixels,
                                             40, 30, self_shadow.pixels);
  EXPECT_EQ(with_edge.false_shadow, 60);
  EXPECT_DOUBLE_EQ(with_edge.false_shadow_band, 60.0 / (20 * 30));
  EXPECT_EQ(interior(with_edge), 0.0);
  EXPECT_DOUBLE_EQ(with_edge.max_distance_px, 1.0);
  const MaskErrors without = compare(technique, truth, receivers);
  EXPECT_DOUBLE_EQ(without.false_shadow_interior, 60.0 / (20 * 30));
  technique.fill(22, 0, 23, 30, 1);   // a third column: two pixels from the edge, interior
  const MaskErrors wider = compare_masks(technique.pixels, truth.pixels, receivers.pixels, 40,
                                         30, self_shadow.pixels);
  EXPECT_DOUBLE_EQ(wider.false_shadow_interior, 30.0 / (20 * 30));
}

// A receiver of the truth whose outline pixel the technique's frame left as background (the
// rasteriser's outline a hair inside the exact one) shows no shadow decision: with `drawn` it is
// left out of the count and reported, where without it the same pixel, whose neighbours are all
// background, is an interior error. A drawn pixel that is wrong still counts.
TEST(CompareMasks, ReceiverPixelsTheFrameLeftAsBackgroundAreNotCounted) {
  Mask truth(40, 30), technique(40, 30), receivers(40, 30), drawn(40, 30);
  receivers.fill(10, 10, 30, 20, 1);  // a receiver in shadow on a background
  truth.fill(10, 10, 30, 20, 1);
  drawn.fill(10, 10, 30, 20, 1);
  technique = truth;
  receivers.fill(30, 15, 31, 16, 1);  // one more pixel of it in the truth, alone on its right
  truth.fill(30, 15, 31, 16, 1);
  const MaskErrors without = compare(technique, truth, receivers);
  EXPECT_EQ(without.false_light, 1);
  EXPECT_EQ(without.undrawn_receiver_pixels, 0);
  const MaskErrors with = compare_masks(technique.pixels, truth.pixels, receivers.pixels, 40, 30,
                                        {}, drawn.pixels);
  EXPECT_EQ(with.undrawn_receiver_pixels, 1);
  EXPECT_EQ(with.receiver_pixels, 20 * 10);
  EXPECT_EQ(with.false_light, 0);
  EXPECT_EQ(with.misclassified, 0.0);
  technique.fill(20, 15, 21, 16, 0);  // a drawn pixel inside the shadow left lit: interior
  const MaskErrors wrong = compare_masks(technique.pixels, truth.pixels, receivers.pixels, 40,
                                         30, {}, drawn.pixels);
  EXPECT_EQ(wrong.false_light, 1);
  EXPECT_DOUBLE_EQ(wrong.false_light_interior, 1.0 / (20 * 10));
}

// Deterministic pseudo-random masks so the test is repeatable.
std::uint32_t next(std::uint32_t &state) {
  state = state * 1664525u + 1013904223u;
  return state >> 8;
}

TEST(CompareMasks, FractionsAddUpAndDistanceMatchesBruteForce) {
  const int w = 53, h = 37;
  Mask truth(w, h), technique(w, h), receivers(w, h, 1);
  truth.fill(8, 6, 30, 25, 1);
  truth.fill(35, 20, 50, 33, 1);
  technique = truth;
  std::uint32_t state = 12345;
  for (auto &p : technique.pixels)
    if (next(state) % 9 == 0) p ^= 1;
  for (auto &r : receivers.pixels)
    if (next(state) % 11 == 0) r = 0;
  const MaskErrors e = compare(technique, truth, receivers);

  ASSERT_GT(e.false_shadow, 0);
  ASSERT_GT(e.false_light, 0);
  EXPECT_GT(interior(e), 0.0);
  EXPECT_GT(e.false_shadow_band + e.false_light_band, 0.0);
  EXPECT_NEAR(e.false_shadow_band + e.false_shadow_interior + e.false_light_band +
                  e.false_light_interior,
              e.misclassified, 1e-12);
  EXPECT_DOUBLE_EQ(e.misclassified, double(e.false_shadow + e.false_light) / static_cast<double>(e.receiver_pixels));

  auto at = [&](const Mask &m, int x, int y) { return m.pixels[std::size_t(y) * w + x]; };
  auto on_boundary = [&](int x, int y) {
    if (!at(receivers, x, y)) return false;
    const int n[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
    for (const auto &q : n)
      if (q[0] >= 0 && q[1] >= 0 && q[0] < w && q[1] < h && at(receivers, q[0], q[1]) &&
          at(truth, q[0], q[1]) != at(truth, x, y))
        return true;
    return false;
  };
  double farthest = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!at(receivers, x, y) || at(technique, x, y) == at(truth, x, y)) continue;
      double nearest = 1e300;
      for (int by = 0; by < h; ++by)
        for (int bx = 0; bx < w; ++bx)
          if (on_boundary(bx, by)) nearest = std::min(nearest, std::hypot(bx - x, by - y));
      farthest = std::max(farthest, nearest);
    }
  EXPECT_NEAR(e.max_distance_px, farthest, 1e-9);
}

// The tool compares full frames; one boundary pixel far from most wrong pixels is the worst case
// for the distance to the true edge, which must still be exact.
TEST(CompareMasks, FarthestWrongPixelOfAFullFrameIsExact) {
  Mask truth(640, 480), technique(640, 480, 1);
  truth.fill(0, 0, 1, 1, 1);
  const MaskErrors e = compare(technique, truth);
  EXPECT_NEAR(e.max_distance_px, std::hypot(638.0, 479.0), 1e-9);  // far corner to (1,0)
}

}  // namespace
