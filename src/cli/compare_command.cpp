// `glideshadows compare A.png B.png`: image errors, and for two masks the shadow errors split
// into the edge band and the interior, B being the truth.
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
};

int run_compare(const CompareOptions &o) {
  ImageErrors errors;
  std::string error;
  if (!compare_images(o.a, o.b, o.diff, errors, error)) {
    std::fprintf(stderr, "glideshadows compare: %s\n", error.c_str());
    return 1;
  }
  std::printf("mean error %.6f, max error %.6f, PSNR %.2f dB, %ld pixels differ by more than 1/255\n",
              errors.mean, errors.max, errors.psnr, errors.pixels_over_threshold);
  std::vector<std::uint8_t> ma, mb;
  int wa = 0, ha = 0, wb = 0, hb = 0;
  if (read_mask(o.a, ma, wa, ha, error) && read_mask(o.b, mb, wb, hb, error) && wa == wb && ha == hb) {
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
  compare->add_option("a", o->a, "an image, or a technique's mask")->required();
  compare->add_option("b", o->b, "the reference image, or the true mask")->required();
  compare->add_option("--diff", o->diff, "write a heat map of the difference (PNG)");
  return {compare, [o] { return run_compare(*o); }};
}

}  // namespace gs::cli
