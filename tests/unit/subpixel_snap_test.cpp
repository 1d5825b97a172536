// snap_to_subpixel (geometry/projection.h): the 12.4 snap without a library call gives
// std::round(pixels * 16) / 16 to the bit, halves away from zero, the sign of a zero, and the
// floats past 2^23 sixteenths, infinities and NaN as they are.
#include "techniques/geometry/projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

namespace {

std::uint32_t bits(float value) {
  std::uint32_t b = 0;
  std::memcpy(&b, &value, sizeof b);
  return b;
}

float reference(float pixels) { return std::round(pixels * 16.0f) / 16.0f; }

::testing::AssertionResult same_as_round(float pixels) {
  const float snapped = gs::snap_to_subpixel(pixels), expected = reference(pixels);
  if (bits(snapped) == bits(expected) || (std::isnan(snapped) && std::isnan(expected))) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << pixels << " snaps to " << snapped << ", std::round gives "
                                       << expected;
}

TEST(SubpixelSnap, HalvesGoAwayFromZero) {
  EXPECT_EQ(gs::snap_to_subpixel(1.0f / 32.0f), 1.0f / 16.0f);
  EXPECT_EQ(gs::snap_to_subpixel(-1.0f / 32.0f), -1.0f / 16.0f);
  EXPECT_EQ(gs::snap_to_subpixel(3.0f / 32.0f), 2.0f / 16.0f);
  EXPECT_EQ(gs::snap_to_subpixel(100.0f + 5.0f / 32.0f), 100.0f + 3.0f / 16.0f);
  // Just below a half goes down, just above goes up.
  EXPECT_EQ(gs::snap_to_subpixel(std::nextafter(1.0f / 32.0f, 0.0f)), 0.0f);
  EXPECT_EQ(gs::snap_to_subpixel(std::nextafter(1.0f / 32.0f, 1.0f)), 1.0f / 16.0f);
}

TEST(SubpixelSnap, KeepsTheSignOfZero) {
  EXPECT_EQ(bits(gs::snap_to_subpixel(0.01f)), bits(0.0f));
  EXPECT_EQ(bits(gs::snap_to_subpixel(-0.01f)), bits(-0.0f));
  EXPECT_EQ(bits(gs::snap_to_subpixel(-0.0f)), bits(-0.0f));
}

TEST(SubpixelSnap, MatchesStdRoundEverywhere) {
  // Every half and its neighbours over the guard band's range and past 2^23 sixteenths.
  for (int k = -200000; k <= 200000; k += 7) {
    const float half = (static_cast<float>(k) + 0.5f) / 16.0f;
    for (float v : {half, std::nextafter(half, -INFINITY), std::nextafter(half, INFINITY)}) {
      ASSERT_TRUE(same_as_round(v));
      ASSERT_TRUE(same_as_round(-v));
    }
  }
  for (float v : {524287.97f, 524288.0f, 524288.03f, 1.0e7f, -1.0e7f, 3.0e38f,
                  std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                  std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::denorm_min()}) {
    EXPECT_TRUE(same_as_round(v));
  }
  std::mt19937 random(22);
  std::uniform_real_distribution<float> screen(-4000.0f, 4000.0f);
  std::uniform_int_distribution<std::uint32_t> any_bits;
  for (int i = 0; i < 200000; ++i) {
    ASSERT_TRUE(same_as_round(screen(random)));
    const std::uint32_t b = any_bits(random);
    float v = 0.0f;
    std::memcpy(&v, &b, sizeof v);
    ASSERT_TRUE(same_as_round(v));
  }
}

}  // namespace
