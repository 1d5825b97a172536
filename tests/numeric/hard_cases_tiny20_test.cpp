// Issue 14: the projected techniques on a floor seen from a camera 7 and 10 cm above it at
// 160x120 (planar19's scenes; tests/hard_cases/README.md, "tiny20"). Three things:
// - The edge-error budget's base (receiver_screen_pixels) counts about what the error measure
//   counts: the pixels the frame draws a surface at (the Voodoo's 1/16-pixel snap leaves a
//   floor's far triangles thinner than it undrawn), with those an object shadows on itself
//   alone, which only the truth's rays know.
// - A receiver triangle thinner than the snap loses its pixel centres to a neighbour whose
//   shadow texture coordinates there are not the surface's: box0's whole shadow (5 pixels on
//   the floor's one row) was left lit, served with an estimate of 0. Such centres now count
//   as wrong pixels against the budget, and the shadow is refused by name.
// - The budget is whole pixels: under 1,000 receiver pixels it is 0, and any stray the
//   estimate sees is refused (fighter1's 0.01 px at 10 cm, one pixel wrong, 0.208%).
#include "hard_case_checks.h"

#include "techniques/light_passes/scene_pass.h"
#include "techniques/texel_error/shadow_edge_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// Some refusal of `o` holds every part of `parts`.
bool refused_with(const Outcome &o, const std::vector<std::string> &parts) {
  for (const std::string &e : o.refusals) {
    bool all = true;
    for (const std::string &part : parts) all = all && e.find(part) != std::string::npos;
    if (all) return true;
  }
  return false;
}

const std::string kSnap = "thinner than the Voodoo's 1/16-pixel snap";

}  // namespace

// Before: 487 and 513 against the measure's 478 and 512 (counted and self-shadowed only); now
// 480 and 512. The 320x240 scene and dl1 agreed already.
TEST(HardCases, EdgeErrorBudgetCountsThePixelsTheErrorMeasureCounts) {
  for (const char *file : {"audit/planar19_camera_7cm_160x120.json",
                           "audit/planar19_camera_10cm_160x120.json",
                           "audit/planar19_camera_7cm_light_west.json",
                           "audit/dl1_cylinder_through_plate_light_along_it.json"}) {
    const gs::Scene scene = load(file);
    const Truth truth = truth_of(scene);
    const Outcome o = run("planar", scene, truth);
    long self_only_drawn = 0;
    for (std::size_t i = 0; i < truth.self_only.size(); ++i) {
      self_only_drawn += truth.self_only[i] && o.drawn[i];
    }
    // The base covers the snapped triangles alone, so it also counts the few centres the snap
    // adds just outside an outline against the background (2 of 480 at 7 cm): at most 1%.
    const long base =
        static_cast<long>(gs::receiver_screen_pixels(scene, gs::project_scene(scene)));
    const long measured = o.errors.receiver_pixels + self_only_drawn;
    EXPECT_GE(base, measured) << file << ": counted " << o.errors.receiver_pixels
                              << ", self-shadowed only " << self_only_drawn;
    EXPECT_LE(base, measured + measured / 100) << file << ": counted " << o.errors.receiver_pixels
                                               << ", self-shadowed only " << self_only_drawn;
    EXPECT_EQ(gs::edge_error_budget(scene, gs::project_scene(scene)),
              std::floor(gs::kEdgeErrorReceiverShare * static_cast<float>(base)))
        << file;
  }
}

// Before: both projected techniques served it with none of box0's shadow drawn (1.046%
// misclassified, 0.209% interior, the estimate 0). The other techniques draw its 5 pixels.
TEST(HardCases, ProjectedRefusesAShadowTheSnapTakesFromAFloorStrip) {
  const std::string file = "audit/tiny20_floor_7cm_box0_only_160x120.json";
  const gs::Scene scene = load(file);
  const Truth truth = truth_of(scene);
  ASSERT_GE(truth.shadow_pixels, 5) << file << ": no shadow, the case tests nothing";
  for (const std::string &name : kProjectedTechniques) {
    const Outcome o = run(name, scene, truth);
    report(file + " " + name, o);
    expect_clean_glide(name, o);
    EXPECT_TRUE(refused_with(o, {"light 0 and 'box0': ", kSnap})) << file << " " << name;
  }
  for (const char *name : {"planar", "depth-map", "stencil-volume"}) {
    const Outcome o = run(name, scene, truth);
    report(file + " " + name, o);
    for (const std::string &e : o.refusals) ADD_FAILURE() << file << " " << name << ": " << e;
    EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
        << file << " " << name;
  }
}

// Before: 1.119% (7 cm: box0's shadow missing, and one false shadow pixel on the crumpled sheet
// from fighter1's) and 0.208% (10 cm: that pixel) interior error, both projected techniques,
// served. Now box0's shadow is refused at 7 cm, and fighter1's at 10 cm: its estimate, 0.01 px,
// is over a budget of 0 whole pixels (512 receiver pixels).
TEST(HardCases, ProjectedRefusesTheFloorStripShadowsItCannotPlaceByName) {
  const std::string seven = "audit/planar19_camera_7cm_160x120.json";
  const std::string ten = "audit/planar19_camera_10cm_160x120.json";
  const gs::Scene scene7 = load(seven), scene10 = load(ten);
  const Truth truth7 = truth_of(scene7), truth10 = truth_of(scene10);
  for (const std::string &name : kProjectedTechniques) {
    const Outcome o7 = run(name, scene7, truth7);
    report(seven + " " + name, o7);
    EXPECT_TRUE(refused_with(o7, {"light 0 and 'box0': ", kSnap})) << seven << " " << name;
    const Outcome o10 = run(name, scene10, truth10);
    report(ten + " " + name, o10);
    EXPECT_TRUE(refused_with(o10, {"light 0 and 'fighter1': the shadow texels would move its edges",
                                   "(the largest accepted is 0, "}))
        << ten << " " << name;
  }
}
