// Spotlights with beam maps (Segal et al. 1992, 3.2): the beam patterns and attenuation as
// functions, then the Glide passes against them: a white floor under a spotlight, every pixel's
// value against albedo x (ambient + light x diffuse x beam x attenuation) at the floor point the
// pixel sees; exact per-pixel attenuation against the per-vertex kind on a floor of two
// triangles, where interpolating between corners is far from the function.
#include "techniques/geometry/projection.h"
#include "techniques/light_passes/scene_pass.h"
#include "scene/spotlight.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <functional>
#include <vector>

namespace {

constexpr int kSpotWidth = 160, kSpotHeight = 120;

gs::SpotLight spotlight(const std::string &beam) {
  gs::SpotLight light;
  light.position = {0, 6, 0};
  light.target = {0, 0, 0};
  light.cone_degrees = 40.0f;
  light.beam = beam;
  return light;
}

TEST(BeamPattern, RoundIsFullInsideAndDarkAtTheRim) {
  const gs::SpotLight light = spotlight("round");
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {0.0f, 0.0f}), 1.0f);
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {0.0f, 0.79f}), 1.0f);
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {0.0f, 1.0f}), 0.0f);
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {0.8f, 0.8f}), 0.0f);  // r = 1.13: outside the disc
  EXPECT_GT(gs::beam_intensity(light, {0.9f, 0.0f}), 0.2f);        // the soft edge
  EXPECT_LT(gs::beam_intensity(light, {0.9f, 0.0f}), 0.8f);
}

TEST(BeamPattern, SquareLightsTheCornersTheRoundOneLeavesDark) {
  const gs::SpotLight light = spotlight("square");
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {0.8f, 0.8f}), 1.0f);
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {-0.8f, 0.84f}), 1.0f);
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {1.0f, 0.0f}), 0.0f);
}

TEST(BeamPattern, GoboBarsCutTheBeamIntoFourPanes) {
  const gs::SpotLight light = spotlight("gobo");
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {0.0f, 0.5f}), 0.0f);
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {0.5f, 0.04f}), 0.0f);
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {0.4f, 0.4f}), 1.0f);
  EXPECT_FLOAT_EQ(gs::beam_intensity(light, {-0.4f, -0.4f}), 1.0f);
}

TEST(BeamPattern, LensRingsCrowdTowardsTheRim) {
  // Bright rings where 3 r (1 + 0.4 r^2) is a whole number: r = 0 and about 0.31 and 0.57.
  const gs::SpotLight light = spotlight("lens");
  auto at = [&](float r) { return gs::beam_intensity(light, {r, 0.0f}); };
  EXPECT_FLOAT_EQ(at(0.0f), 1.0f);
  float first_peak = 0.2f, second_peak = 0.45f;
  for (float r = 0.2f; r < 0.45f; r += 0.001f) first_peak = at(r) > at(first_peak) ? r : first_peak;
  for (float r = 0.45f; r < 0.7f; r += 0.001f) second_peak = at(r) > at(second_peak) ? r : second_peak;
  EXPECT_NEAR(first_peak, 0.318f, 0.005f);
  EXPECT_NEAR(second_peak, 0.585f, 0.01f);
  EXPECT_LT(second_peak - first_peak, first_peak) << "distortion should narrow the outer rings";
}

TEST(BeamPattern, TexelsSampleTheBeamWithABlackBorder) {
  const gs::SpotLight light = spotlight("square");
  const int side = 32;
  const std::vector<std::uint8_t> texels = gs::beam_texels(light, side);
  ASSERT_EQ(texels.size(), static_cast<std::size_t>(side * side));
  for (int i = 0; i < side; ++i) {
    EXPECT_EQ(texels[static_cast<std::size_t>(i)], 0);                         // top row
    EXPECT_EQ(texels[static_cast<std::size_t>((side - 1) * side + i)], 0);     // bottom row
    EXPECT_EQ(texels[static_cast<std::size_t>(i * side)], 0);                  // left column
    EXPECT_EQ(texels[static_cast<std::size_t>(i * side + side - 1)], 0);       // right column
  }
  EXPECT_EQ(texels[static_cast<std::size_t>(16 * side + 16)], 255);
}

TEST(Attenuation, FollowsTheInverseQuadraticOfTheAxialDistance) {
  gs::SpotLight light = spotlight("round");
  EXPECT_FLOAT_EQ(gs::distance_attenuation(light, 50.0f), 1.0f) << "mode none attenuates nothing";
  light.attenuation = {gs::AttenuationMode::PerPixel, 1.0f, 0.5f, 0.25f};
  EXPECT_FLOAT_EQ(gs::distance_attenuation(light, 2.0f), 1.0f / 3.0f);
  EXPECT_FLOAT_EQ(gs::distance_attenuation(light, 0.0f), 1.0f);
  light.attenuation.constant = 0.1f;  // 1 / 0.1 would brighten: clamped to 1
  EXPECT_FLOAT_EQ(gs::distance_attenuation(light, 0.0f), 1.0f);
  // The axial distance is the light-view depth: equal across a plane facing the light.
  EXPECT_FLOAT_EQ(gs::axial_distance(light, {0, 0, 0}), 6.0f);
  EXPECT_FLOAT_EQ(gs::axial_distance(light, {3, 0, -2}), 6.0f);
  const std::vector<std::uint8_t> ramp = gs::attenuation_texels(light, 2.0f, 6.0f, 4);
  ASSERT_EQ(ramp.size(), 4u);
  for (int i = 0; i < 4; ++i) {  // texel centres at 2.5, 3.5, 4.5, 5.5 m
    const float d = 2.5f + static_cast<float>(i);
    EXPECT_EQ(ramp[static_cast<std::size_t>(i)],
              std::lround(255.0f / (0.1f + 0.5f * d + 0.25f * d * d)));
  }
}

class SpotlightPassTest : public ::testing::Test {
 protected:
  void SetUp() override {
    grGlideInit();
    ASSERT_TRUE(glideShimSetWindowSize(kSpotWidth, kSpotHeight));
    ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                             GR_ORIGIN_UPPER_LEFT, 2, 1));
  }
  void TearDown() override { grGlideShutdown(); }

  // A white 12 m floor (y = 0) in `divisions` quads per side, no ambient, the camera above.
  static gs::Scene floor_scene(const gs::SpotLight &light, int divisions) {
    gs::Scene scene;
    scene.width = kSpotWidth, scene.height = kSpotHeight;
    scene.ambient = glm::vec3(0.0f);
    gs::SceneObject floor;
    floor.name = "floor";
    floor.mesh = gs::make_plane(12.0f, divisions);
    floor.mesh.set_color(glm::vec3(1.0f));
    scene.objects.push_back(floor);
    scene.lights.push_back(light);
    scene.camera.position = {0, 11, 0.01f};
    scene.camera.target = {0, 0, 0};
    scene.camera.fov_degrees = 60.0f;
    return scene;
  }

  // The green channel (6 bits, the finest) of every pixel, 0..1.
  static std::vector<float> render_green(const gs::Scene &scene) {
    gs::render_scene(scene, gs::project_scene(scene));
    std::vector<FxU16> frame(kSpotWidth * kSpotHeight);
    grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, kSpotWidth, kSpotHeight, kSpotWidth * 2, frame.data());
    std::vector<float> green(frame.size());
    for (std::size_t i = 0; i < frame.size(); ++i)
      green[i] = static_cast<float>(frame[i] >> 5 & 0x3F) / 63.0f;
    return green;
  }

  // Calls `visit` with the floor point (world) each pixel centre sees, through the camera.
  static void for_each_floor_point(
      const gs::Scene &scene, const std::function<void(std::size_t, const glm::vec3 &)> &visit) {
    const glm::mat4 inverse = glm::inverse(
        gs::camera_projection(scene.camera, kSpotWidth, kSpotHeight) * gs::camera_view(scene.camera));
    for (int y = 0; y < kSpotHeight; ++y) {
      for (int x = 0; x < kSpotWidth; ++x) {
        // Normalised device coordinates of the pixel centre, y up.
        const float nx = (static_cast<float>(x) + 0.5f) / kSpotWidth * 2.0f - 1.0f;
        const float ny = 1.0f - (static_cast<float>(y) + 0.5f) / kSpotHeight * 2.0f;
        const glm::vec4 near = inverse * glm::vec4(nx, ny, -1.0f, 1.0f);
        const glm::vec4 far = inverse * glm::vec4(nx, ny, 1.0f, 1.0f);
        const glm::vec3 a = glm::vec3(near) / near.w, b = glm::vec3(far) / far.w;
        const float t = a.y / (a.y - b.y);
        const glm::vec3 point = a + (b - a) * t;
        if (std::abs(point.x) < 5.9f && std::abs(point.z) < 5.9f)
          visit(static_cast<std::size_t>(y * kSpotWidth + x), point);
      }
    }
  }

  static float expected_light(const gs::SpotLight &light, const glm::vec3 &point) {
    glm::vec2 uv;
    if (!gs::beam_coordinates(light, point, uv)) return 0.0f;
    const float diffuse = glm::normalize(light.position - point).y;  // the floor's normal is +y
    return std::min(1.0f, diffuse * gs::beam_intensity(light, uv) *
                              gs::distance_attenuation(light, gs::axial_distance(light, point)));
  }
};

TEST_F(SpotlightPassTest, FloorFollowsTheBeamMap) {
  for (const char *beam : {"round", "square", "gobo", "lens"}) {
    SCOPED_TRACE(beam);
    const gs::SpotLight light = spotlight(beam);
    const gs::Scene scene = floor_scene(light, 48);
    const std::vector<float> green = render_green(scene);
    int compared = 0, within_two_steps = 0, lit = 0;
    double total_error = 0.0;
    for_each_floor_point(scene, [&](std::size_t pixel, const glm::vec3 &point) {
      const float expected = expected_light(light, point);
      const float error = std::abs(green[pixel] - expected);
      ++compared;
      total_error += error;
      within_two_steps += error <= 2.0f / 63.0f;
      lit += green[pixel] > 0.5f;
    });
    ASSERT_GT(compared, kSpotWidth * kSpotHeight / 2);
    EXPECT_GT(lit, 500) << "the beam lit almost nothing";
    // Where the pattern's edges fall within a texel of the 128x128 map, bilinear filtering and
    // the pixel's own footprint blur them: a few percent of pixels, never the mean.
    EXPECT_LT(total_error / compared, 1.5 / 63.0);
    EXPECT_GT(within_two_steps, compared * 95 / 100);
  }
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(SpotlightPassTest, ExactAttenuationFollowsDepthWherePerVertexInterpolates) {
  // A light looking down the length of a floor of two triangles at 37 degrees: the light-space
  // depth runs from 3.6 m to 13.2 m across each triangle, and 1 / (1 + 0.1 d^2) is far from
  // linear over it, while the diffuse term stays between 0.4 and 0.7 at the corners.
  gs::SpotLight light = spotlight("square");
  light.position = {0, 6.0f, 6.0f};
  light.target = {0, 0, -2};
  light.cone_degrees = 100.0f;
  light.attenuation = {gs::AttenuationMode::PerPixel, 1.0f, 0.0f, 0.1f};
  const std::vector<float> exact = render_green(floor_scene(light, 1));
  light.attenuation.mode = gs::AttenuationMode::PerVertex;
  const std::vector<float> per_vertex = render_green(floor_scene(light, 1));
  light.attenuation.mode = gs::AttenuationMode::None;
  const gs::Scene unattenuated_scene = floor_scene(light, 1);
  const std::vector<float> unattenuated = render_green(unattenuated_scene);

  // Each mode's attenuation, seen as its frame over the unattenuated one (same vertex diffuse and
  // beam), against the function at the pixel's own depth; where enough light makes the ratio
  // meaningful in 6 bits.
  gs::SpotLight function_of_depth = light;
  function_of_depth.attenuation.mode = gs::AttenuationMode::PerPixel;
  double exact_error = 0.0, vertex_error = 0.0;  // mean absolute error of the ratio
  int compared = 0;
  for_each_floor_point(unattenuated_scene, [&](std::size_t pixel, const glm::vec3 &point) {
    if (unattenuated[pixel] < 0.3f) return;
    const float function =
        gs::distance_attenuation(function_of_depth, gs::axial_distance(light, point));
    exact_error += std::abs(exact[pixel] / unattenuated[pixel] - function);
    vertex_error += std::abs(per_vertex[pixel] / unattenuated[pixel] - function);
    ++compared;
  });
  ASSERT_GT(compared, 1000);
  exact_error /= compared, vertex_error /= compared;
  EXPECT_LT(exact_error, 0.03) << "exact attenuation should follow the function per pixel";
  EXPECT_GT(vertex_error, std::max(0.08, 4.0 * exact_error))
      << "per-vertex attenuation over a 10 m triangle should not";
  std::printf("mean attenuation error: exact %.4f, per vertex %.4f over %d pixels\n", exact_error,
              vertex_error, compared);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

}  // namespace
