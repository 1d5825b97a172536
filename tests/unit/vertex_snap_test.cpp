// The 12.4 vertex snap (glide_shim::snap) against its definition, std::round(v * 16) / 16, bit
// for bit: on a sweep of coordinates across the setup range, on every half-way case of a band
// of it (which std::round takes away from zero), on the neighbours of those, and on the signed
// zeros and values beyond the integer conversion's range.
#include "draw.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace {

std::uint32_t bits(float v) {
  std::uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

float defined_snap(float v) { return std::round(v * 16.0f) / 16.0f; }

TEST(VertexSnap, MatchesRoundingOnASweepOfTheSetupRange) {
  int checked = 0;
  for (float v = -33000.0f; v <= 33000.0f; v += 0.0137f, ++checked) {
    ASSERT_EQ(bits(glide_shim::snap(v)), bits(defined_snap(v))) << "at " << v;
  }
  EXPECT_GT(checked, 4000000);
}

TEST(VertexSnap, RoundsHalvesAwayFromZeroAndTheirNeighboursToNearest) {
  for (int k = -20000; k <= 20000; ++k) {
    const float half = (static_cast<float>(k) + 0.5f) / 16.0f;  // exact: a half 1/16 step
    for (float v : {half, std::nextafter(half, 0.0f), std::nextafter(half, 2.0f * half)}) {
      ASSERT_EQ(bits(glide_shim::snap(v)), bits(defined_snap(v))) << "at " << v;
    }
  }
}

TEST(VertexSnap, KeepsSignedZerosAndLargeValues) {
  for (float v : {0.0f, -0.0f, -0.01f, 0.01f, -0.03125f, 0.03125f, 3.0e9f, -3.0e9f, 1.0e30f,
                  std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                  8388608.5f, -8388607.5f}) {
    EXPECT_EQ(bits(glide_shim::snap(v)), bits(defined_snap(v))) << "at " << v;
  }
}

}  // namespace
