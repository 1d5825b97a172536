// The size a refusal names (shadow_edge_error.h, smallest_accepted_size): the smallest doubling
// of the map at which both the texel footprint and the frame's estimated edge error fit. Before,
// a footprint refusal named the size the footprint alone would take, and rendering at that size
// could be refused again along the shadow's edges.
#include "techniques/texel_error/shadow_edge_error.h"

#include <gtest/gtest.h>

#include <optional>

namespace {

gs::EdgeErrorEstimate estimate(float at1, float at2, float at4, float at8) {
  gs::EdgeErrorEstimate e;
  e.pixels[0] = at1, e.pixels[1] = at2, e.pixels[2] = at4, e.pixels[3] = at8;
  return e;
}

TEST(AcceptedSize, FootprintAloneHalvesAsTheSizeDoubles) {
  // 12 px at 256 against 5 px accepted: 6 at 512, 3 at 1024.
  const gs::AcceptedSize a =
      gs::smallest_accepted_size(256, 4096, 12.0f, 5.0f, estimate(0, 0, 0, 0), std::nullopt);
  EXPECT_EQ(a.size, 1024);
  EXPECT_EQ(gs::accepted_size_words(a), "size 1024 would be accepted");
}

TEST(AcceptedSize, EdgeErrorCanAskForMoreThanTheFootprint) {
  // The footprint fits at 1024; the edges (51 px accepted) only at 2048.
  const gs::AcceptedSize a = gs::smallest_accepted_size(256, 4096, 12.0f, 5.0f,
                                                        estimate(276, 90, 57, 18), 51.0f);
  EXPECT_EQ(a.size, 2048);
}

TEST(AcceptedSize, PastTheEstimatedSizesTheErrorHalvesWithEachDoubling) {
  // Estimated up to 8 times the size (256 here); 120 px at 256 is taken as 60 at 512 and 30 at
  // 1024, the first within 51.
  const gs::AcceptedSize a =
      gs::smallest_accepted_size(32, 4096, 1.0f, 5.0f, estimate(400, 300, 200, 120), 51.0f);
  EXPECT_EQ(a.size, 1024);
  const gs::AcceptedSize never =
      gs::smallest_accepted_size(32, 512, 1.0f, 5.0f, estimate(400, 300, 200, 120), 51.0f);
  EXPECT_EQ(never.size, 0);
  EXPECT_EQ(never.largest_tried, 512);
  EXPECT_EQ(gs::accepted_size_words(never), "no size up to 512 would be accepted");
}

TEST(AcceptedSize, NeverBeyondTheTechniquesLargest) {
  const gs::AcceptedSize a =
      gs::smallest_accepted_size(128, 512, 40.0f, 5.0f, estimate(0, 0, 0, 0), std::nullopt);
  EXPECT_EQ(a.size, 0);
  EXPECT_EQ(a.largest_tried, 512);
}

}  // namespace
