// The slide projector's passes (Segal et al. 1992) against their equations: depth only; add the
// slide where z equals the stored depth; modulate by the surface colour. A white floor under a
// checker slide from straight above: lit cells are albedo x min(1, ambient + slide), dark ones
// albedo x ambient; outside the projector's view only ambient; behind the projector nothing.
#include "techniques/light_passes/scene_pass.h"
#include "techniques/light_passes/slide_projector.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace {

constexpr int kSlideWidth = 160, kSlideHeight = 120;

class SlideProjectorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    grGlideInit();
    ASSERT_TRUE(glideShimSetWindowSize(kSlideWidth, kSlideHeight));
    ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                             GR_ORIGIN_UPPER_LEFT, 2, 1));
  }
  void TearDown() override { grGlideShutdown(); }

  static gs::Scene floor_under_projector(const glm::vec3 &albedo) {
    gs::Scene scene;
    scene.width = kSlideWidth, scene.height = kSlideHeight;
    scene.ambient = glm::vec3(0.25f);
    gs::SceneObject floor;
    floor.name = "floor";
    floor.mesh = gs::make_plane(20.0f, 8);
    floor.mesh.set_color(albedo);
    scene.objects.push_back(floor);
    gs::SpotLight projector;
    projector.position = {0, 6, 0};
    projector.target = {0, 0, 0};
    projector.cone_degrees = 30.0f;  // a footprint of about 3.2 m on a 20 m floor
    projector.slide = "checker";
    scene.lights.push_back(projector);
    scene.camera.position = {0, 12, 0.01f};
    scene.camera.target = {0, 0, 0};
    scene.camera.fov_degrees = 60.0f;
    return scene;
  }

  static std::vector<FxU16> render(const gs::Scene &scene) {
    gs::render_scene(scene, gs::project_scene(scene));
    std::vector<FxU16> frame(kSlideWidth * kSlideHeight);
    grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, kSlideWidth, kSlideHeight, kSlideWidth * 2, frame.data());
    return frame;
  }
};

TEST_F(SlideProjectorTest, PixelsFollowThePassEquations) {
  // Albedo (0.5, 1, 1): lit red = 0.5 x min(1, 0.25 + 1) -> 8-bit ~127 -> 565 red 15;
  // lit green saturates the sum, then x 1 -> 63; dark red = 0.5 x 0.25 -> ~31 -> 3.
  const std::vector<FxU16> frame = render(floor_under_projector({0.5f, 1.0f, 1.0f}));
  int lit = 0, dark = 0, centre_lit = 0;
  for (int y = 0; y < kSlideHeight; ++y) {
    for (int x = 0; x < kSlideWidth; ++x) {
      const FxU16 p = frame[static_cast<std::size_t>(y * kSlideWidth + x)];
      const int r = p >> 11, g = p >> 5 & 0x3F;
      if (std::abs(r - 15) <= 1 && g >= 62) {
        ++lit;
        centre_lit += std::abs(x - kSlideWidth / 2) < 20 && std::abs(y - kSlideHeight / 2) < 20;
      }
      dark += std::abs(r - 3) <= 1 && std::abs(g - 15) <= 1;
    }
  }
  // The 3.2 m footprint is ~37 px across: ~680 px of white cells, less the bilinear transitions
  // between cells 4-5 px wide, leaves a few hundred exactly lit pixels.
  EXPECT_GT(lit, 150) << "no lit checker cells, or wrong lit value";
  EXPECT_GT(centre_lit, 100) << "lit cells not under the projector";
  EXPECT_GT(dark, kSlideWidth * kSlideHeight / 2) << "the ambient-only floor has the wrong value";
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(SlideProjectorTest, OnlyWhatTheProjectorSeesIsLit) {
  // Outside the projector's 30-degree view the floor is ambient only: the image corners.
  const std::vector<FxU16> frame = render(floor_under_projector(glm::vec3(1.0f)));
  for (int corner : {0, kSlideWidth - 1, (kSlideHeight - 1) * kSlideWidth, kSlideHeight * kSlideWidth - 1}) {
    EXPECT_EQ(frame[static_cast<std::size_t>(corner)] >> 11, (255 / 4) >> 3) << "corner " << corner;
  }
}

TEST_F(SlideProjectorTest, NothingBehindTheProjectorIsLit) {
  // The projector turned to look up, away from the floor: its mirrored (negative) projection
  // must not land on the floor.
  gs::Scene scene = floor_under_projector(glm::vec3(1.0f));
  scene.lights[0].target = {0, 12, 0};
  const std::vector<FxU16> frame = render(scene);
  for (FxU16 p : frame) ASSERT_EQ(p >> 11, (255 / 4) >> 3);
}

}  // namespace
