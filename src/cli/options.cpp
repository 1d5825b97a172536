// The options and set-up the subcommands share (options.h).
#include "cli/options.h"

#include <glide.h>
#include <glide_shim.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace gs::cli {

CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string &input) {
        const double value = std::strtod(input.c_str(), nullptr);
        return std::isfinite(value) ? std::string() : "must be a finite number, not " + input;
      },
      "FINITE");
}

std::vector<int> shadow_sizes() { return {32, 64, 128, 256, 512, 1024, 2048, 4096}; }

void add_technique_options(CLI::App &command, TechniqueChoice &choice, int &shadow_size) {
  command.add_option("--technique", choice.name, "shadow technique")
      ->check(CLI::IsMember(technique_names()))
      ->capture_default_str();
  command.add_option("--shadow-size", shadow_size,
                     "shadow map side in texels, 32..4096; the projected techniques draw at most 512 "
                     "(four 256x256 textures, a Voodoo 1 limit), the depth map up to 4096")
      ->check(CLI::IsMember(shadow_sizes()))
      ->capture_default_str();
  // A depth-map refusal may name a size above 512 ("size 1024 would be accepted"); the projected
  // techniques cannot draw one, so the pair is refused as a command line before anything runs.
  command.parse_complete_callback([&choice, &shadow_size] {
    const bool projected = choice.name == "projected" || choice.name == "projected-chroma";
    if (projected && shadow_size > kLargestProjectedSize) {
      throw CLI::ValidationError(
          "--shadow-size", std::to_string(shadow_size) + ": the " + choice.name +
                               " technique draws at most " + std::to_string(kLargestProjectedSize) +
                               " texels (four 256x256 Voodoo textures); sizes up to 4096 are for "
                               "--technique depth-map");
    }
  });
  command.add_flag("--direct-path", choice.direct_path,
                   "step 1 renders straight into texture memory instead of the back buffer + LFB read");
  command.add_flag("--point", choice.point, "point-sample the shadow texture (default bilinear)");
  command.add_flag("--affine", choice.affine,
                   "divide (s,t) per vertex as the article's listing does (default per pixel)");
  command.add_flag("--auto-size", choice.auto_size,
                   "texture size follows the caster's size on screen (the article's LOD idea)");
  // A pair, so that a command whose default is on (demo: `choice` says so on entry) can be
  // turned off.
  command.add_flag("--grow-size,!--no-grow-size", choice.grow_size,
                   std::string("projected: a shadow refused as too coarse for the screen is drawn at "
                               "the smallest larger size up to 512 the estimates accept, for that "
                               "caster and frame (") +
                       (choice.grow_size ? "on" : "off") + " by default)");
  command.add_option("--alpha", choice.alpha, "iterated alpha: constant (170) or distance")
      ->check(CLI::IsMember({"constant", "distance"}))
      ->capture_default_str();
  command.add_option("--bias-slope", choice.bias_slope, "depth-map: glPolygonOffset factor")
      ->check(finite_number())
      ->check(CLI::Range(0.0f, 100.0f))
      ->capture_default_str();
  command.add_option("--bias-units", choice.bias_units, "depth-map: glPolygonOffset units")
      ->check(finite_number())
      ->check(CLI::Range(0.0f, 10000.0f))
      ->capture_default_str();
  command.add_option("--bias-bound", choice.bias_bound,
                     "depth-map: the slope term moves a caster back by at most this many texels' "
                     "widths at its depth")
      ->check(finite_number())
      ->check(CLI::Range(0.0f, 1000.0f))
      ->capture_default_str();
  command.add_option("--bias-receiver", choice.bias_receiver,
                     "depth-map: a receiver's depth is lowered by this share of its own depth "
                     "change across a texel")
      ->check(finite_number())
      ->check(CLI::Range(0.0f, 100.0f))
      ->capture_default_str();
  command.add_flag("--nearest", choice.nearest,
                   "depth-map: nearest comparison instead of percentage-closer filtering");
  command.add_option("--volume", choice.volume, "stencil-volume: auto, zpass or zfail")
      ->check(CLI::IsMember({"auto", "zpass", "zfail"}))
      ->capture_default_str();
}

TechniqueOptions technique_options(const TechniqueChoice &choice, int shadow_size) {
  TechniqueOptions all;
  ProjectedShadowOptions &options = all.projected;
  options.size = shadow_size;
  options.auto_size = choice.auto_size;
  options.grow_to_accepted = choice.grow_size;
  options.bilinear = !choice.point;
  options.direct_path = choice.direct_path;
  options.chroma_key = choice.name == "projected-chroma";
  options.projective = !choice.affine;
  options.alpha = choice.alpha == "distance" ? ShadowAlpha::Distance : ShadowAlpha::Constant;
  all.depth_bias_slope = choice.bias_slope;
  all.depth_bias_units = choice.bias_units;
  all.depth_bias_bound = choice.bias_bound;
  all.depth_bias_receiver = choice.bias_receiver;
  all.depth_map_linear = !choice.nearest;
  using Mode = TechniqueOptions::VolumeMode;
  all.volume_mode = choice.volume == "zpass"   ? Mode::ZPass
                    : choice.volume == "zfail" ? Mode::ZFail
                                               : Mode::Automatic;
  return all;
}

bool open_window(int width, int height) {
  grGlideInit();
  if (!glideShimSetWindowSize(width, height) ||
      !grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    std::fprintf(stderr, "glideshadows: cannot open a %dx%d Glide window: %s\n", width, height,
                 glideShimGetLastErrorMessage());
    return false;
  }
  grGammaCorrectionValue(0.8f);  // Listing 4
  return true;
}

bool parse_size(const std::string &text, int &width, int &height) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) return false;
  const char *begin = text.data(), *middle = begin + x, *end = begin + text.size();
  const std::from_chars_result w = std::from_chars(begin, middle, width);
  const std::from_chars_result h = std::from_chars(middle + 1, end, height);
  if (w.ec != std::errc() || w.ptr != middle || h.ec != std::errc() || h.ptr != end) return false;
  return width >= 64 && height >= 64 && width <= 2048 && height <= 2048;
}

}  // namespace gs::cli
