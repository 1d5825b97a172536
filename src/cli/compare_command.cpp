// `glideshadows compare A.png B.png`: image errors, and, when the two are shadow masks, the shadow
// errors split into the edge band and the interior, B being the truth. It says which comparison
// it made: masks when both files are black and white (or --as masks), colour images otherwise.
#include "cli/commands.h"
#include "measure/metrics.h"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace gs::cli {
namespace {

struct CompareOptions {
  std::string a, b, diff;
  std::string as = "auto";  // auto, masks or images
};

// Which comparison to make, and the reason printed with it.
struct CompareKind {
  bool masks = false;
  std::string reason;
};

CompareKind choose_kind(const std::string &as, bool a_black_and_white, bool b_black_and_white) {
  if (as == "masks") return {true, "--as masks: a pixel with any colour channel above half is shadow"};
  if (as == "images") return {false, "--as images"};
  if (a_black_and_white && b_black_and_white) return {true, "both are black and white"};
  if (!a_black_and_white && !b_black_and_white) return {false, "neither is black and white"};
  return {false, std::string(a_black_and_white ? "B" : "A") + " is not black and white"};
}

int run_compare(const CompareOptions &o) {
  ImageErrors errors;
  std::string error;
  if (!compare_images(o.a, o.b, o.diff, errors, error)) {
    std::fprintf(stderr, "glideshadows compare: %s\n", error.c_str());
    return 1;
  }
  std::vector<std::uint8_t> ma, mb;
  int wa = 0, ha = 0, wb = 0, hb = 0;
  bool a_black_and_white = false, b_black_and_white = false;
  if (!read_mask(o.a, ma, wa, ha, error, &a_black_and_white) ||
      !read_mask(o.b, mb, wb, hb, error, &b_black_and_white)) {
    std::fprintf(stderr, "glideshadows compare: %s\n", error.c_str());
    return 1;
  }
  const CompareKind kind = choose_kind(o.as, a_black_and_white, b_black_and_white);
  std::printf("comparison: %s (%s)\n", kind.masks ? "masks, B the truth" : "colour images",
              kind.reason.c_str());
  std::printf("mean error %.6f, max error %.6f, PSNR %.2f dB, %ld pixels differ by more than 1/255\n",
              errors.mean, errors.max, errors.psnr, errors.pixels_over_threshold);
  if (kind.masks) {
    // compare_images has checked that the sizes agree.
    const std::vector<std::uint8_t> all(ma.size(), 1);
    const MaskErrors m = compare_masks(ma, mb, all, wa, ha);
    std::printf("as masks (B the truth): %.3f%% misclassified: false shadow %.3f%% band + %.3f%% interior, "
                "false light %.3f%% band + %.3f%% interior; farthest wrong pixel %.1f px from the true edge\n",
                100 * m.misclassified, 100 * m.false_shadow_band, 100 * m.false_shadow_interior,
                100 * m.false_light_band, 100 * m.false_light_interior, m.max_distance_px);
  }
  if (!o.diff.empty()) std::printf("heat map: %s\n", o.diff.c_str());
  return 0;
}

}  // namespace

Command add_compare_command(CLI::App &app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App *compare = app.add_subcommand("compare", "compare two images (and, for masks, shadow errors)");
  compare->footer(
      "Prints which comparison it made. Masks: both files black and white (every pixel black or "
      "one grey above half that all the others share, as render --mask and truth write them); "
      "then the shadow errors of A against B as the truth follow the image errors. Colour "
      "images: anything else; image errors only.");
  compare->add_option("a", o->a, "an image, or a technique's mask")->required();
  compare->add_option("b", o->b, "the reference image, or the true mask")->required();
  compare->add_option("--diff", o->diff, "write a heat map of the difference (PNG)");
  compare->add_option("--as", o->as, "auto: masks when both are black and white; masks: threshold "
                                     "any image at half; images: no mask statistics")
      ->check(CLI::IsMember({"auto", "masks", "images"}))
      ->capture_default_str();
  return {compare, [o] { return run_compare(*o); }};
}

}  // namespace gs::cli
