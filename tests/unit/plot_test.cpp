// The speed-against-error plot (plot.h): pareto_front on hand-made sets, and write_plot's PNG
// read back with OpenImageIO (size, something drawn, a front point where the axes put it,
// identical bytes on a second write) plus its errors for no points and an unwritable path.
#include "measure/plot.h"

#include <OpenImageIO/imagebuf.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using gs::PlotPoint;
using Indices = std::vector<std::size_t>;

// The plot's layout (plot area in image pixels), for finding where a point must be drawn.
using namespace gs::plot_layout;

// Axis maxima 100 ms and 5% are already round, so they are the axis tops.
std::vector<PlotPoint> sample_points() {
  return {
      {20.0, 0.02, "planar"},    // front
      {40.0, 0.01, "projected"}, // front
      {60.0, 0.03, "planar"},    // dominated by 0 and 1
      {100.0, 0.0, "depth map"}, // front
      {50.0, 0.05, "stencil"},   // dominated
  };
}

std::string read_bytes(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ParetoFront, ExcludesDominatedPointsAndSortsByTime) {
  EXPECT_EQ(gs::pareto_front(sample_points()), (Indices{0, 1, 3}));
}

TEST(ParetoFront, EqualTimeKeepsOnlyTheLowerError) {
  const std::vector<PlotPoint> points = {{10.0, 0.02, "a"}, {10.0, 0.01, "b"}, {5.0, 0.03, "c"}};
  EXPECT_EQ(gs::pareto_front(points), (Indices{2, 1}));
}

TEST(ParetoFront, ExactDuplicatesBothStayInIndexOrder) {
  const std::vector<PlotPoint> points = {{30.0, 0.0, "x"}, {10.0, 0.02, "b"}, {10.0, 0.02, "a"}};
  EXPECT_EQ(gs::pareto_front(points), (Indices{1, 2, 0}));
}

TEST(ParetoFront, SinglePointIsTheFront) {
  EXPECT_EQ(gs::pareto_front({{7.0, 0.5, "only"}}), (Indices{0}));
}

TEST(ParetoFront, EmptyGivesEmpty) { EXPECT_TRUE(gs::pareto_front({}).empty()); }

TEST(WritePlot, WritesAReadablePngWithTheFrontPointDrawn) {
  const std::string path = testing::TempDir() + "plot_test_sample.png";
  std::string error;
  ASSERT_TRUE(gs::write_plot(sample_points(), "Shadow techniques", path, error)) << error;

  OIIO::ImageBuf img(path);
  ASSERT_TRUE(img.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << img.geterror();
  ASSERT_EQ(img.spec().width, kWidth);
  ASSERT_EQ(img.spec().height, kHeight);
  ASSERT_EQ(img.spec().nchannels, 3);

  const auto is_white = [&](int x, int y) {
    float px[3];
    img.getpixel(x, y, px, 3);
    return px[0] == 1.0f && px[1] == 1.0f && px[2] == 1.0f;
  };
  int non_white = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) non_white += is_white(x, y) ? 0 : 1;
  EXPECT_GT(non_white, 1000);

  // Front point 0: 20 ms of 100, 2% of 5.
  const int x = kPlotLeft + (kPlotRight - kPlotLeft) * 20 / 100;
  const int y = kPlotBottom - (kPlotBottom - kPlotTop) * 2 / 5;
  EXPECT_FALSE(is_white(x, y)) << "at (" << x << ", " << y << ")";
  // Empty plot area well away from every point, line and legend stays white.
  EXPECT_TRUE(is_white(kPlotLeft + 400, kPlotTop + 30));
}

TEST(WritePlot, SameInputGivesIdenticalBytes) {
  const std::string a = testing::TempDir() + "plot_test_a.png";
  const std::string b = testing::TempDir() + "plot_test_b.png";
  std::string error;
  ASSERT_TRUE(gs::write_plot(sample_points(), "Same", a, error)) << error;
  ASSERT_TRUE(gs::write_plot(sample_points(), "Same", b, error)) << error;
  const std::string bytes = read_bytes(a);
  EXPECT_FALSE(bytes.empty());
  EXPECT_EQ(bytes, read_bytes(b));
}

TEST(WritePlot, AllZeroErrorsStillWrite) {
  const std::string path = testing::TempDir() + "plot_test_zero_error.png";
  std::string error;
  EXPECT_TRUE(gs::write_plot({{1.0, 0.0, "a"}, {2.0, 0.0, "b"}}, "Exact", path, error)) << error;
}

TEST(WritePlot, UnwritablePathFailsNamingThePath) {
  const std::string path = testing::TempDir() + "no_such_directory/plot.png";
  std::string error;
  EXPECT_FALSE(gs::write_plot(sample_points(), "Nowhere", path, error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
}

TEST(WritePlot, NoPointsFails) {
  const std::string path = testing::TempDir() + "plot_test_empty.png";
  std::string error;
  EXPECT_FALSE(gs::write_plot({}, "Empty", path, error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(std::ifstream(path).good());
}

}  // namespace
