// split_into_textures (projected_shadow.h) cuts a 512-texel light view into four 256-texel
// tiles, and step 3 clips each receiver to a tile's seams. Neighbouring tiles must cut a
// receiver at the very same points, or the pixels between the two cuts are darkened by neither
// (a crack of false light) or by both. Checked on triangles crossing the seams at many angles:
// every seam point one tile makes is made, bit for bit, by its neighbour, and the four pieces
// cover the triangle's area in the light's view, the parts beyond the map kept (its clean border
// lies there).
#include "techniques/projected/projected_shadow.h"
#include "techniques/geometry/projection.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace {

// A light 4 m above a floor, looking down at it through a wide view, as step 1 may fit one.
gs::LightView whole_view() {
  gs::LightView view;
  view.view = glm::lookAt(glm::vec3(0.3f, 4.0f, 1.1f), glm::vec3(0.0f, 0.0f, -0.4f),
                          glm::vec3(0.0f, 1.0f, 0.0f));
  view.projection = glm::perspective(glm::radians(137.0f), 1.0f, 0.05f, 40.0f);
  view.size = 512;
  view.usable = true;
  return view;
}

// Signed area of a polygon's projection onto the light's image plane (NDC).
double ndc_area(const std::vector<gs::ClipVertex> &polygon, const glm::mat4 &projection) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec4 a = projection * polygon[i].clip;
    const glm::vec4 b = projection * polygon[(i + 1) % polygon.size()].clip;
    twice += static_cast<double>(a.x / a.w) * (b.y / b.w) - static_cast<double>(b.x / b.w) * (a.y / a.w);
  }
  return 0.5 * twice;
}

TEST(TileSeams, NeighbouringTilesCutReceiversAtTheSamePoints) {
  const gs::LightView view = whole_view();
  const std::vector<gs::LightView> tiles = gs::split_into_textures(view);
  ASSERT_EQ(tiles.size(), 4u);
  for (const gs::LightView &tile : tiles) EXPECT_EQ(tile.size, 256);

  std::mt19937 random(7);
  std::uniform_real_distribution<float> floor_coordinate(-9.0f, 9.0f);
  int triangles_across = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<gs::ClipVertex> triangle;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 world(floor_coordinate(random), 0.0f, floor_coordinate(random));
      triangle.push_back({view.view * glm::vec4(world, 1.0f), world, {}});
    }
    // Light view space pieces, one per tile.
    std::vector<std::vector<gs::ClipVertex>> pieces;
    std::vector<gs::ClipVertex> scratch;
    for (const gs::LightView &tile : tiles) {
      std::vector<gs::ClipVertex> piece = triangle;
      for (const glm::vec4 &plane : tile.tile_planes) {
        if (piece.size() < 3) break;
        gs::clip_polygon(piece, plane, scratch);
      }
      if (piece.size() < 3) piece.clear();
      pieces.push_back(piece);
    }
    int tiles_reached = 0;
    for (const auto &piece : pieces) tiles_reached += piece.empty() ? 0 : 1;
    if (tiles_reached < 2) continue;
    ++triangles_across;

    // Every point a tile's cut made (not one of the triangle's corners) is a vertex of
    // another tile's piece too.
    for (std::size_t a = 0; a < pieces.size(); ++a) {
      for (const gs::ClipVertex &v : pieces[a]) {
        bool original = false;
        for (const gs::ClipVertex &corner : triangle) original = original || corner.world == v.world;
        if (original) continue;
        bool shared = false;
        for (std::size_t b = 0; b < pieces.size() && !shared; ++b) {
          if (b == a) continue;
          for (const gs::ClipVertex &w : pieces[b]) shared = shared || w.world == v.world;
        }
        EXPECT_TRUE(shared) << "trial " << trial << ": tile " << a << " cut the receiver at ("
                            << v.world.x << ", " << v.world.z
                            << ") and no neighbour did: a crack between the tiles";
      }
    }
    double covered = 0.0;
    for (const auto &piece : pieces) {
      if (!piece.empty()) covered += ndc_area(piece, view.projection);
    }
    const double whole = ndc_area(triangle, view.projection);
    EXPECT_NEAR(covered, whole, 1e-4 * std::abs(whole) + 1e-8) << "trial " << trial;
  }
  EXPECT_GT(triangles_across, 100) << "too few triangles crossed a seam to test it";
}

}  // namespace
