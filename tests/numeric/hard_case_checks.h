// What the hard-case tests (hard_cases_test.cpp, hard_cases_surfaces_test.cpp) share: the ray-cast
// truth of a scene and the pixels a comparison counts, one technique's frame and mask in a Glide
// window of the scene's size, and the checks every class of issue 14 makes (interior errors at
// most 0.1% of the receiver pixels, or a refusal by name). Masks: 1 where shadowed, rows from the top.
#pragma once

#include "hard_case_scenes.h"

#include "measure/ground_truth.h"
#include "measure/metrics.h"
#include "measure/speed_error.h"
#include "techniques/technique.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace hard_cases {

inline const std::vector<std::string> kTechniques = {"projected", "projected-chroma", "planar",
                                              "depth-map", "stencil-volume"};

// The truth of one scene, and which pixels a comparison counts: visible surfaces, without those
// only their own object shadows (no technique here shadows an object with itself but the depth
// map, and the receivers of these scenes are convex or flat).
struct Truth {
  gs::GroundTruth exact;
  std::vector<std::uint8_t> receivers;
  std::vector<std::uint8_t> self_only;  // left out of the count, in shadow all the same
  long shadow_pixels = 0;
};

inline Truth truth_of(const gs::Scene &scene) {
  Truth truth;
  std::string error;
  EXPECT_TRUE(gs::compute_ground_truth(scene, truth.exact, error)) << error;
  truth.receivers.resize(truth.exact.object.size());
  truth.self_only.resize(truth.exact.object.size());
  for (std::size_t i = 0; i < truth.receivers.size(); ++i) {
    const bool self_only = truth.exact.self_shadow[i] && !truth.exact.shadow[i];
    truth.receivers[i] = truth.exact.object[i] >= 0 && !self_only;
    truth.self_only[i] = truth.exact.object[i] >= 0 && self_only;
    truth.shadow_pixels += truth.exact.shadow[i];
  }
  return truth;
}

// One technique's frame and mask of a scene, in a Glide window of the scene's size.
struct Outcome {
  std::vector<std::uint8_t> mask;  // 1 where the technique darkened the pixel
  std::vector<std::uint8_t> drawn;  // 1 where the frame without shadows drew a surface
  long shadowed = 0;
  gs::MaskErrors errors;
  std::vector<std::string> warnings;
  std::vector<std::string> refusals;  // FrameReport::errors: shadows it says it could not cast
  GlideShimError glide_error = GLIDESHIM_OK;  // any vertex with NaN/inf reaching the
  std::string glide_message;                  // rasterizer is reported here by the shim
};

inline Outcome run(const std::string &name, const gs::Scene &scene, const Truth &truth,
            const gs::TechniqueOptions &options = {}) {
  Outcome outcome;
  std::string error;
  const std::unique_ptr<gs::ShadowTechnique> technique = gs::make_technique(name, options, error);
  EXPECT_TRUE(technique) << error;
  if (!technique) return outcome;
  grGlideInit();
  EXPECT_TRUE(glideShimSetWindowSize(scene.width, scene.height));
  EXPECT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  glideShimClearError();
  const gs::FrameReport frame = technique->render(scene, false);
  outcome.warnings = frame.warnings;
  outcome.refusals = frame.errors;
  technique->render_mask(scene);
  outcome.glide_error = glideShimGetLastError();
  outcome.glide_message = glideShimGetLastErrorMessage();
  std::vector<FxU16> pixels(static_cast<std::size_t>(scene.width) *
                            static_cast<std::size_t>(scene.height));
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, static_cast<FxU32>(scene.width),
                  static_cast<FxU32>(scene.height), static_cast<FxU32>(scene.width) * 2,
                  pixels.data());
  outcome.drawn = gs::drawn_without_shadows(scene);
  grGlideShutdown();
  for (FxU16 p : pixels) outcome.mask.push_back(p != 0);
  outcome.shadowed = std::accumulate(outcome.mask.begin(), outcome.mask.end(), 0L);
  outcome.errors = gs::compare_masks(outcome.mask, truth.exact.shadow, truth.receivers,
                                     scene.width, scene.height, truth.self_only, outcome.drawn);
  return outcome;
}

// What a test measured, printed so a failing threshold shows the numbers behind it.
inline void report(const std::string &what, const Outcome &o) {
  std::cout << "  " << what << ": shadowed " << o.shadowed << " px, misclassified "
            << o.errors.misclassified * 100.0 << "% (false shadow band "
            << o.errors.false_shadow_band * 100.0 << "%, interior "
            << o.errors.false_shadow_interior * 100.0 << "%; false light band "
            << o.errors.false_light_band * 100.0 << "%, interior "
            << o.errors.false_light_interior * 100.0 << "%), farthest "
            << o.errors.max_distance_px << " px; " << o.errors.receiver_pixels << " counted, "
            << o.errors.undrawn_receiver_pixels << " undrawn";
  for (const std::string &w : o.warnings) std::cout << "; warns: " << w;
  for (const std::string &e : o.refusals) std::cout << "; ERROR: " << e;
  std::cout << "\n";
}

// Nothing non-finite reached the rasterizer: the shim refuses such vertices with
// GLIDESHIM_ERR_INVALID_VALUE, and any other error would be a bug too.
inline void expect_clean_glide(const std::string &name, const Outcome &o) {
  EXPECT_EQ(o.glide_error, GLIDESHIM_OK) << name << ": " << o.glide_message;
}

inline bool finite(const GrVertex &v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.oow) &&
         std::isfinite(v.tmuvtx[0].sow) && std::isfinite(v.tmuvtx[0].tow) &&
         std::isfinite(v.tmuvtx[0].oow) && std::isfinite(v.a);
}

// Pixels darkened where the truth says the light does not reach at all (outside its cone, or
// the surface facing away): a shadow from nowhere, e.g. a mirrored back projection, or a shadow
// beyond the beam. Every technique clips its shadows to the beam per pixel (issue 14), so
// `farthest` (how far, in pixels, the farthest such pixel lies from a pixel the light reaches)
// is at most a pixel: the beam's edge sampled at pixel centres.
struct Unlit {
  long pixels = 0;
  int farthest = 0;
};

inline Unlit shadow_where_unlit(const Outcome &o, const Truth &truth, int width, int height) {
  // Chessboard distance to the nearest reached pixel, by breadth-first search from all of them.
  const auto n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<int> distance(n, -1);
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < n; ++i) {
    if (truth.exact.object[i] >= 0 &&
        truth.exact.reach[i * truth.exact.lights] != gs::LightReach::Outside) {
      distance[i] = 0;
      queue.push_back(i);
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int x = static_cast<int>(queue[head] % static_cast<std::size_t>(width));
    const int y = static_cast<int>(queue[head] / static_cast<std::size_t>(width));
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (x + dx < 0 || x + dx >= width || y + dy < 0 || y + dy >= height) continue;
        const auto next = static_cast<std::size_t>((y + dy) * width + x + dx);
        if (distance[next] >= 0) continue;
        distance[next] = distance[queue[head]] + 1;
        queue.push_back(next);
      }
    }
  }
  Unlit unlit;
  for (std::size_t i = 0; i < n; ++i) {
    if (!o.mask[i] || truth.exact.object[i] < 0 ||
        truth.exact.reach[i * truth.exact.lights] != gs::LightReach::Outside) {
      continue;
    }
    ++unlit.pixels;
    unlit.farthest = std::max(unlit.farthest, distance[i] < 0 ? width + height : distance[i]);
  }
  return unlit;
}


// ---- issue 14: shadows that are never silently wrong ----------------------------------------
// Every technique either reports success with interior errors (wrong pixels more than a pixel
// from the true edge) on at most 0.1% of the receiver pixels, or refuses with an error naming
// what it cannot shadow (`refusals`: technique -> a part of the message) and casts nothing from it.
inline constexpr double kInteriorBudget = 0.001;

// What a check accepts besides each technique served within the budget or refused as its
// `refusals` say.
struct Leeway {
  // True shadow pixels of one object on another that the frame must hold to test anything: 150
  // by default (ne2's grazed floor holds 195); fewer where a floor seen edge-on is a strip a few
  // pixels tall, and 0 where the frame's shadows are all objects' own (which the truth leaves
  // out of the count).
  long least_shadow = 150;
  // When not empty, a technique that `refusals` does not name may refuse instead of serving, with
  // an error containing this (the light, or the light and the caster it cannot shadow).
  std::string refusal_naming;
};

// The techniques of `names` on `scene` as loaded from `file` (or varied from it; `file` names
// it in the messages). only_in_beam off for scenes of several lights (shadow_where_unlit asks
// light 0 alone).
inline void expect_these_right_or_refused(const std::string &file, const gs::Scene &scene,
                                          const std::vector<std::string> &names,
                                          const std::map<std::string, std::string> &refusals,
                                          bool only_in_beam, const Leeway &leeway = {}) {
  const Truth truth = truth_of(scene);
  ASSERT_GE(truth.shadow_pixels, leeway.least_shadow) << file << ": too little shadow to test";
  for (const std::string &name : names) {
    const Outcome o = run(name, scene, truth);
    report(file + " " + name, o);
    expect_clean_glide(name, o);
    ASSERT_GT(o.errors.receiver_pixels, 0) << file << " " << name << ": no receiver pixels";
    const auto refused = refusals.find(name);
    if (refused != refusals.end()) {
      ASSERT_FALSE(o.refusals.empty()) << file << " " << name << ": should refuse, not pass";
      EXPECT_NE(o.refusals[0].find(refused->second), std::string::npos) << o.refusals[0];
      continue;
    }
    if (!leeway.refusal_naming.empty() && !o.refusals.empty()) {
      EXPECT_NE(o.refusals[0].find(leeway.refusal_naming), std::string::npos) << o.refusals[0];
      continue;
    }
    for (const std::string &e : o.refusals) ADD_FAILURE() << file << " " << name << ": " << e;
    EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
        << file << " " << name;
    // Pixels left out as undrawn are the receivers' outline against the background, which the
    // Voodoo's 1/16-pixel vertex snap moves by up to a pixel (the ray cast starts on the camera's
    // near plane, as clipping does, so the near plane cuts both alike). Far more would mean the
    // frame without shadows lost surfaces, and a check over what is left would pass without
    // looking.
    EXPECT_LE(o.errors.undrawn_receiver_pixels, 10 + o.errors.receiver_pixels / 20)
        << file << " " << name;
    if (only_in_beam) {
      EXPECT_LE(shadow_where_unlit(o, truth, scene.width, scene.height).farthest, 1)
          << file << " " << name << ": shadow where the light does not shine";
    }
  }
}

// Every technique on `scene`.
inline void expect_right_or_refused(const std::string &file, const gs::Scene &scene,
                                    const std::map<std::string, std::string> &refusals = {},
                                    bool only_in_beam = true) {
  expect_these_right_or_refused(file, scene, kTechniques, refusals, only_in_beam);
}

inline void expect_right_or_refused(const std::string &file,
                                    const std::map<std::string, std::string> &refusals = {},
                                    bool only_in_beam = true) {
  expect_right_or_refused(file, hard_cases::load(file), refusals, only_in_beam);
}

// The two projected techniques (the texture read bilinear, and by chroma key).
inline const std::vector<std::string> kProjectedTechniques = {"projected", "projected-chroma"};

// Both projected techniques on the scene of `file` served within the budget, none refusing.
inline void expect_projected_right(const std::string &file) {
  expect_these_right_or_refused(file, hard_cases::load(file), kProjectedTechniques, {}, true);
}

}  // namespace hard_cases
