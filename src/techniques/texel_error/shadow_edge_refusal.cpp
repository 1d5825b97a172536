// The sizes a too-coarse projected shadow would be accepted at, and the words of its refusal
// (shadow_edge_error.h): the light, the caster, the screen pixels its edges would stray over
// against the frame's budget, and the size that would do.
#include "techniques/texel_error/shadow_edge_error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace gs {

AcceptedSize smallest_accepted_size(int size, int largest_size, float footprint,
                                    float largest_footprint, const EdgeErrorEstimate &within_budget,
                                    const std::optional<float> &largest_edge_pixels) {
  AcceptedSize accepted;
  for (int doubling = 0, tried = size; tried <= largest_size; ++doubling, tried *= 2) {
    accepted.largest_tried = tried;
    const bool footprint_fits =
        footprint * static_cast<float>(size) / static_cast<float>(tried) <= largest_footprint;
    // Past the sizes estimated, the largest one's error halves with each doubling: a shadow
    // edge strays by a share of a texel's width.
    const int estimated = std::min(doubling, EdgeErrorEstimate::kSizes - 1);
    const bool edges_fit =
        !largest_edge_pixels ||
        std::ldexp(within_budget.pixels[estimated], estimated - doubling) <= *largest_edge_pixels;
    if (footprint_fits && edges_fit) {
      accepted.size = tried;
      break;
    }
  }
  return accepted;
}

std::string accepted_size_words(const AcceptedSize &accepted) {
  return accepted.size ? "size " + std::to_string(accepted.size) + " would be accepted"
                       : "no size up to " + std::to_string(accepted.largest_tried) +
                             " would be accepted";
}

std::string shadow_edge_error_message(const Scene &scene, std::size_t light, std::size_t caster,
                                      std::size_t receiver, float taken,
                                      const EdgeErrorEstimate &frame, float largest_pixels,
                                      int size, const AcceptedSize &accepted) {
  return shadow_edge_error_reason(scene, light, caster, receiver, taken, frame, largest_pixels,
                                  size, accepted) +
         "; " + kCastsNoShadow;
}

std::string shadow_edge_error_reason(const Scene &scene, std::size_t light, std::size_t caster,
                                     std::size_t receiver, float taken,
                                     const EdgeErrorEstimate &frame, float largest_pixels,
                                     int size, const AcceptedSize &accepted) {
  // An estimate under one pixel to a hundredth: a budget of 0 (edge_error_budget) refuses any.
  char pixels[240];
  std::snprintf(pixels, sizeof pixels,
                "%.*f screen pixels (the largest accepted is %.0f, 0.1%% of the receivers' "
                "pixels; %.*f of them taken by the frame's other shadows)",
                frame.pixels[0] < 1.0f ? 2 : 0, static_cast<double>(frame.pixels[0]),
                static_cast<double>(largest_pixels), taken < 1.0f && taken > 0.0f ? 2 : 0,
                static_cast<double>(taken));
  return "light " + std::to_string(light) + " and '" + scene.objects[caster].name +
         "': the shadow texels would move its edges beyond their band over about " + pixels +
         ", most on '" + scene.objects[receiver].name + "', so the " + std::to_string(size) +
         "-texel shadow is too coarse for the screen (" + accepted_size_words(accepted) +
         ")";
}

std::string snapped_receivers_reason(const Scene &scene, std::size_t light, std::size_t caster,
                                     int lost, float taken, float largest_pixels) {
  char budget[160];
  std::snprintf(budget, sizeof budget,
                "the largest accepted is %.0f, 0.1%% of the receivers' pixels; %.*f of them "
                "taken by the frame's other shadows",
                static_cast<double>(largest_pixels), taken < 1.0f && taken > 0.0f ? 2 : 0,
                static_cast<double>(taken));
  return "light " + std::to_string(light) + " and '" + scene.objects[caster].name + "': " +
         std::to_string(lost) +
         " pixel centres near its shadow lie on receiver triangles thinner than the Voodoo's "
         "1/16-pixel snap, which draws them with a neighbour's shadow texture coordinates, "
         "not the surface's there (" + budget + ")";
}

}  // namespace gs
