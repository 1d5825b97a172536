// Issue 14 for the depth map: its texels too coarse for the screen near a wide cone's rim (the
// class "depth-map texels too coarse" of tests/hard_cases/README.md, and the audit's a2 and a3),
// and curved receivers shadowing themselves under a low light (the class "curved receivers in
// their own shadow", and the audit's i6). Each run either refuses by name (a map texel spans more
// screen pixels than depth_map_footprint.h's limit where a shadow edge can lie) or stays within
// the interior-error budget against the ray-cast truth.
#include "hard_case_checks.h"

#include "scene/fight_scene.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// The depth map on `scene` at each size, percentage-closer or nearest: the sizes it refused;
// every other size must be within the budget, and a refused size's every refusal must name the
// light, the caster and the receiver and say which size would be accepted.
std::set<int> depth_map_fine_or_refused(const std::string &file, const gs::Scene &scene,
                                        const std::vector<int> &sizes, bool linear) {
  const Truth truth = truth_of(scene);  // a3 has no true shadow: what it tests is false shadow
  std::set<int> refused;
  for (int size : sizes) {
    gs::TechniqueOptions options;
    options.projected.size = size;
    options.depth_map_linear = linear;
    const std::string what =
        file + (linear ? " pcf" : " nearest") + " size " + std::to_string(size);
    const Outcome o = run("depth-map", scene, truth, options);
    report(what, o);
    expect_clean_glide(what, o);
    if (!o.refusals.empty()) {
      refused.insert(size);
      for (const std::string &e : o.refusals) {
        EXPECT_EQ(e.rfind("light 0 and '", 0), 0u) << e;
        EXPECT_NE(e.find("screen pixels (the largest accepted is"), std::string::npos) << e;
        EXPECT_NE(e.find(std::to_string(size) + "-texel shadow is too coarse for the screen (size "),
                  std::string::npos)
            << e;
      }
      continue;
    }
    EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
        << what;
  }
  return refused;
}

// Whether the depth map at its defaults refuses nothing in `scene`.
bool depth_map_accepts(const std::string &file, const gs::Scene &scene) {
  std::string error;
  const auto technique = gs::make_technique("depth-map", {}, error);
  if (!technique) {
    ADD_FAILURE() << file << ": " << error;
    return false;
  }
  grGlideInit();
  EXPECT_TRUE(glideShimSetWindowSize(scene.width, scene.height));
  EXPECT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1));
  const gs::FrameReport frame = technique->render(scene, false);
  grGlideShutdown();
  for (const std::string &e : frame.errors) ADD_FAILURE() << file << ": " << e;
  return frame.errors.empty();
}

const std::vector<int> kMapSizes = {64, 128, 256, 512};

}  // namespace

// Wide cones (140 to 160 degrees) with casters whose shadows run out towards the rim: every size
// right or refused, with either lookup, and the sizes refused those measured with
// `hard_case_sweeps depth-footprint` (docs/hard_cases_sweeps.md): the hall needs 1024 texels
// (7.2 px at 512), a pillar's shadow 5.4 px at 512 (measured within 0.1%: refused all the same).
TEST(HardCases, DepthMapWideConeTexelsRightOrRefused) {
  const std::map<std::string, std::set<int>> expected = {
      {"wide_cone_hall.json", {64, 128, 256, 512}},
      {"wide_cone_pillars.json", {64, 128, 256, 512}},
      {"wide_cone_crates.json", {64}},
      {"audit/a2_corridor_walls.json", {64, 128, 256}},
      {"audit/a3_lean_to_roof.json", {64, 128}}};
  for (const auto &[file, refused_sizes] : expected) {
    const gs::Scene scene = load(file);
    for (bool linear : {true, false}) {
      EXPECT_EQ(depth_map_fine_or_refused(file, scene, kMapSizes, linear), refused_sizes)
          << file << (linear ? " pcf" : " nearest");
    }
  }
}

// The audit's corridor at the size its file asks for (256, measured 0.34% interior error before
// the check) is refused by name; at 512 it is right.
TEST(HardCases, DepthMapRefusesTheCorridorAtItsOwnSize) {
  const gs::Scene scene = load("audit/a2_corridor_walls.json");
  const Truth truth = truth_of(scene);
  const Outcome o = run("depth-map", scene, truth);
  report("a2_corridor_walls.json depth-map", o);
  ASSERT_FALSE(o.refusals.empty());
  EXPECT_NE(o.refusals[0].find("wall': a shadow texel spans"), std::string::npos) << o.refusals[0];
  EXPECT_NE(o.refusals[0].find("on 'floor', so the 256-texel shadow is too coarse for the screen "
                               "(size 512 would be accepted)"),
            std::string::npos)
      << o.refusals[0];
}

// Curved receivers shadowing themselves: every technique right or refused by name (stencil
// volumes: the open ground casts no volume).
TEST(HardCases, CurvedReceiversInTheirOwnShadow) {
  for (const char *file : {"waves_low_sun.json", "dunes_side_light.json", "ripples_grazing.json"}) {
    const std::map<std::string, std::string> refusals = {{"stencil-volume", "is not a closed mesh"}};
    expect_right_or_refused(file, refusals);
  }
}

// The waves with the light 8 to 40 degrees above them and 0.3 to 1.2 m high, and the audit's i6
// at several sizes: the depth map's acne (0.23% at the old slope of 2) is gone with either lookup.
TEST(HardCases, DepthMapWavesWithoutAcne) {
  for (float elevation : {8.0f, 15.0f, 25.0f, 40.0f}) {
    for (float amplitude : {0.3f, 0.6f, 1.2f}) {
      const std::string name = "waves_low_sun.json at " + std::to_string(elevation) +
                               " degrees, " + std::to_string(amplitude) + " m";
      const gs::Scene scene = waves_low_sun(elevation, amplitude);
      for (bool linear : {true, false}) {
        EXPECT_TRUE(depth_map_fine_or_refused(name, scene, {256}, linear).empty()) << name;
      }
    }
  }
  const gs::Scene i6 = load("audit/i6_post_in_valley_hill_casts.json");
  for (bool linear : {true, false}) {
    EXPECT_TRUE(
        depth_map_fine_or_refused("i6_post_in_valley_hill_casts.json", i6, {128, 256, 512}, linear)
            .empty());
  }
}

// The check refuses none of the project's sample scenes, nor the fight's bench frames at 640x480
// with 256 texels, at the depth map's defaults.
TEST(HardCases, DepthMapFootprintRefusesNoSampleOrFightFrame) {
  for (const auto &entry : std::filesystem::directory_iterator(
           std::filesystem::path(GLIDESHADOWS_HARD_CASES_DIR) / "../../scenes")) {
    if (entry.path().extension() != ".json") continue;
    gs::Scene scene;
    std::string error;
    ASSERT_TRUE(gs::load_scene(entry.path().string(), scene, error)) << error;
    EXPECT_TRUE(depth_map_accepts(entry.path().filename().string(), scene));
  }
  gs::FightScene fight(640, 480, 256);
  for (float time : {0.5f, 2.1f, 5.3f}) {
    EXPECT_TRUE(depth_map_accepts("fight t=" + std::to_string(time), fight.at(time)));
  }
}
