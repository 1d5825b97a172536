// What several subcommands share: the technique options (--technique, --shadow-size, ...), the
// Glide window every rendering command opens, and parsing of a WxH screen size.
#pragma once

#include "techniques/technique.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace gs::cli {

// The technique's options as the command line spells them.
struct TechniqueChoice {
  std::string name = "projected";
  bool direct_path = false, point = false, affine = false, auto_size = false;
  bool grow_size = false;  // --grow-size (ProjectedShadowOptions::grow_to_accepted)
  std::string alpha = "constant";
  float bias_slope = 1.0f, bias_units = 4.0f;  // depth-map polygon offset (technique.h)
  float bias_bound = 6.0f;     // depth-map: the slope term's largest push, texels (technique.h)
  float bias_receiver = 0.5f;  // depth-map: the receiver's own slope taken off (technique.h)
  bool nearest = false;                       // depth-map filtering
  std::string volume = "auto";                // stencil-volume mode
};

// A check for a number option that refuses "nan" and "inf", to run before CLI::Range (which
// lets NaN through: every comparison with it is false).
CLI::Validator finite_number();

// The sides --shadow-size takes: powers of two 32..4096. A scene file's shadow_size stays within
// 32..512 (docs/scene_format.md), what every technique draws; only the depth map goes beyond.
std::vector<int> shadow_sizes();
constexpr int kLargestProjectedSize = 512;

void add_technique_options(CLI::App &command, TechniqueChoice &choice, int &shadow_size);
TechniqueOptions technique_options(const TechniqueChoice &choice, int shadow_size);

// grGlideInit and a width x height window with the article's gamma (Listing 4); false with a
// message on stderr when the shim refuses.
bool open_window(int width, int height);

// "WxH", two decimal integers, each side 64..2048; a number too long for an int fails like any
// other bad text.
bool parse_size(const std::string &text, int &width, int &height);

}  // namespace gs::cli
