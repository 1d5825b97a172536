// Error of a technique's shadow mask against the ground truth, split the way the field reads
// it: pixels within one pixel of the true shadow boundary (sampling error) and the rest (real
// mistakes: missing shadows, acne, leaks, back projection), as fractions of the receiver pixels,
// plus the farthest a wrong pixel lies from the true boundary. Whole images: mean, max, PSNR.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace gs {

struct MaskErrors {
  long receiver_pixels = 0;          // pixels the comparison counts (visible surfaces)
  // Receiver pixels of the truth that the frame left as background, not counted: outline pixels
  // the Voodoo's 1/16-pixel vertex snap moves the edge past, and what the near plane clips.
  long undrawn_receiver_pixels = 0;
  long false_shadow = 0, false_light = 0;
  double false_shadow_band = 0.0;    // fractions of receiver_pixels
  double false_shadow_interior = 0.0;
  double false_light_band = 0.0;
  double false_light_interior = 0.0;
  double misclassified = 0.0;        // all four together
  double max_distance_px = 0.0;      // from a wrong pixel to the nearest true boundary pixel
};

// `technique` and `truth` are 0/1 per pixel (rows from the top); `receivers` marks the pixels
// that count (1) and those that do not (0: background, or excluded such as self-shadow).
// `uncounted_shadow` (empty, or 0/1 per pixel) marks pixels left out of the count that are in
// shadow all the same (an object's shadow on itself): their edge against a counted pixel the
// truth calls lit is a true shadow edge, so a wrong pixel beside it is sampling, not interior.
// `drawn` (empty, or 0/1 per pixel) marks the pixels where the frame drew a surface (the frame
// without shadows, drawn_without_shadows in speed_error.h): a receiver pixel of the truth that
// the frame leaves as background shows no shadow decision at all, so it is not counted either.
MaskErrors compare_masks(const std::vector<std::uint8_t> &technique,
                         const std::vector<std::uint8_t> &truth,
                         const std::vector<std::uint8_t> &receivers, int width, int height,
                         const std::vector<std::uint8_t> &uncounted_shadow = {},
                         const std::vector<std::uint8_t> &drawn = {});

struct ImageErrors {
  double mean = 0.0, max = 0.0, psnr = 0.0;  // channel values 0..1; PSNR in dB
  long pixels_over_threshold = 0;
};

// Compares two images of the same size through OpenImageIO (media/image_files.h); writes a heat
// map of the difference (black: none, through red and yellow to white: the largest) when `heat_map` is not empty.
bool compare_images(const std::string &a, const std::string &b, const std::string &heat_map,
                    ImageErrors &errors, std::string &error);

// The same comparison of two 8-bit RGB images in memory (rows from the top, 3 bytes a pixel);
// false with `error` when the sizes disagree or the image files module cannot be loaded.
bool compare_rgb(const std::vector<std::uint8_t> &a, const std::vector<std::uint8_t> &b,
                 int width, int height, ImageErrors &errors, std::string &error);

// Reads a mask PNG (any pixel with a channel above half is 1). With `black_and_white`, also says
// whether the image is a mask as `render --mask` and `truth` write them: every pixel either black
// or one grey above half that all the others share (colour channels equal; alpha ignored).
bool read_mask(const std::string &path, std::vector<std::uint8_t> &mask, int &width, int &height,
               std::string &error, bool *black_and_white = nullptr);

}  // namespace gs
