// Mask and image error metrics (metrics.h): misclassified receiver pixels split into the ±1-pixel
// band around the true shadow boundary and the interior, the farthest wrong pixel from that
// boundary (exact Euclidean distance transform, Felzenszwalb & Huttenlocher 2012), and whole-image
// mean / max / PSNR through OpenImageIO (the image files module, media/image_files.h) with an
// optional heat map of the difference.
#include "measure/metrics.h"

#include "media/image_files.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gs {

namespace {

// PSNR reported for identical images, where OIIO gives +inf. Finite so that CSV/JSON output and
// plots stay valid; far above what any two images differing by one 16-bit level in one channel
// can reach (96.3 dB + 10·log10(channel values), under 190 dB for a billion values), so it
// cannot be mistaken for a measurement.
constexpr double kIdenticalPsnrDb = 999.0;

// One 8-bit level. OIIO counts a failure when |A−B| > threshold, and a one-level difference read
// back as float can land a rounding error above 1/255; the margin keeps one level from counting.
constexpr float kFailThreshold = 1.0f / 255.0f + 1e-6f;

constexpr double kFar = 1e20;  // squared distance standing for "no boundary pixel"
constexpr double kInf = std::numeric_limits<double>::infinity();

// Exact squared Euclidean distance transform of one line (Felzenszwalb & Huttenlocher):
// d[q] = min_p (q−p)² + f[p], the lower envelope of the parabolas rooted at every p.
std::vector<double> distance_1d(const std::vector<double> &f) {
  const int n = static_cast<int>(f.size());
  std::vector<int> v(n);         // roots of the parabolas on the envelope
  std::vector<double> z(n + 1);  // where each envelope parabola takes over
  int k = 0;
  z[0] = -kInf;
  z[1] = kInf;
  for (int q = 1; q < n; ++q) {
    double s = 0.0;
    for (;;) {
      const int p = v[k];
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s > z[k]) break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  std::vector<double> d(n);
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    d[q] = dq * dq + f[v[k]];
  }
  return d;
}

// Squared distance from every pixel to the nearest pixel with seed != 0: columns, then rows.
std::vector<double> squared_distance(const std::vector<std::uint8_t> &seed, int width, int height) {
  std::vector<double> grid(seed.size());
  for (std::size_t i = 0; i < seed.size(); ++i) grid[i] = seed[i] ? 0.0 : kFar;
  std::vector<double> column(height);
  for (int x = 0; x < width; ++x) {
    for (int y = 0; y < height; ++y) column[y] = grid[std::size_t(y) * width + x];
    const std::vector<double> d = distance_1d(column);
    for (int y = 0; y < height; ++y) grid[std::size_t(y) * width + x] = d[y];
  }
  for (int y = 0; y < height; ++y) {
    const auto row = grid.begin() + std::ptrdiff_t(y) * width;
    const std::vector<double> d = distance_1d(std::vector<double>(row, row + width));
    std::copy(d.begin(), d.end(), row);
  }
  return grid;
}

// Black → red → yellow → white, t in 0..1, one third of the range per step.
void heat_colour(float t, unsigned char rgb[3]) {
  const float s = 3.0f * std::clamp(t, 0.0f, 1.0f);
  const float channel[3] = {s, s - 1.0f, s - 2.0f};
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<unsigned char>(std::lround(255.0f * std::clamp(channel[c], 0.0f, 1.0f)));
}

bool read_image(const media::ImageFiles &files, const std::string &path, media::FloatImage &image,
                std::string &error) {
  std::string why;
  if (!files.read(path, image, why)) {
    error = "cannot read image '" + path + "': " + why;
    return false;
  }
  return true;
}

bool write_heat_map(const media::ImageFiles &files, const media::FloatImage &a,
                    const media::FloatImage &b, const std::string &path, std::string &error) {
  const int w = a.width, h = a.height, nc = a.channels;
  const std::vector<float> &pa = a.pixels, &pb = b.pixels;
  std::vector<float> diff(std::size_t(w) * h, 0.0f);
  for (std::size_t i = 0; i < diff.size(); ++i)
    for (int c = 0; c < nc; ++c)
      diff[i] = std::max(diff[i], std::fabs(pa[i * nc + c] - pb[i * nc + c]));
  const float largest = *std::max_element(diff.begin(), diff.end());
  std::vector<unsigned char> rgb(diff.size() * 3);
  for (std::size_t i = 0; i < diff.size(); ++i)
    heat_colour(largest > 0.0f ? diff[i] / largest : 0.0f, &rgb[i * 3]);
  std::string why;
  if (!files.write_rgb(path, "png", w, h, rgb.data(), why)) {
    error = "cannot write heat map '" + path + "': " + why;
    return false;
  }
  return true;
}

}  // namespace

MaskErrors compare_masks(const std::vector<std::uint8_t> &technique,
                         const std::vector<std::uint8_t> &truth,
                         const std::vector<std::uint8_t> &truth_receivers, int width, int height,
                         const std::vector<std::uint8_t> &uncounted_shadow,
                         const std::vector<std::uint8_t> &drawn) {
  MaskErrors errors;
  const std::size_t count = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
  // The API has no error channel: inputs shorter than width·height compare nothing.
  if (count == 0 || technique.size() < count || truth.size() < count ||
      truth_receivers.size() < count)
    return errors;
  std::vector<std::uint8_t> receivers(truth_receivers.begin(), truth_receivers.begin() + long(count));
  if (drawn.size() >= count) {
    for (std::size_t i = 0; i < count; ++i) {
      if (!receivers[i] || drawn[i]) continue;
      receivers[i] = 0;
      ++errors.undrawn_receiver_pixels;
    }
  }
  auto at = [width](int x, int y) { return std::size_t(y) * width + x; };

  // Boundary: a receiver whose 4-neighbour is also a receiver with the other truth value. The
  // neighbour must be a receiver because the edge of a receiver against the background (or an
  // excluded surface) is a silhouette, not a shadow edge. Both sides of an edge are boundary.
  // A lit receiver beside an uncounted pixel in shadow is boundary too: that is a shadow's edge.
  const bool self_edges = uncounted_shadow.size() >= count;
  std::vector<std::uint8_t> boundary(count, 0);
  bool any_boundary = false;
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = at(x, y);
      if (!receivers[i]) continue;
      for (int k = 0; k < 4 && !boundary[i]; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
        const std::size_t j = at(nx, ny);
        if (receivers[j] && (truth[j] != 0) != (truth[i] != 0)) boundary[i] = 1;
        if (self_edges && !receivers[j] && uncounted_shadow[j] && truth[i] == 0) boundary[i] = 1;
      }
      any_boundary = any_boundary || boundary[i];
    }
  const std::vector<double> d2 = squared_distance(boundary, width, height);

  // With no boundary a wrong pixel is near nothing: it is interior and its distance is the image
  // diagonal, an upper bound on every real distance that marks the case without being infinite.
  const double diagonal = std::hypot(double(width), double(height));
  long fs_band = 0, fs_interior = 0, fl_band = 0, fl_interior = 0;
  double max_d2 = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    if (!receivers[i]) continue;
    ++errors.receiver_pixels;
    const bool t = technique[i] != 0, g = truth[i] != 0;
    if (t == g) continue;
    // Integer offsets with dx² + dy² <= 2 are exactly those with Chebyshev distance <= 1.
    const bool band = any_boundary && d2[i] <= 2.0;
    if (t)
      ++(band ? fs_band : fs_interior);
    else
      ++(band ? fl_band : fl_interior);
    max_d2 = std::max(max_d2, any_boundary ? d2[i] : diagonal * diagonal);
  }
  errors.false_shadow = fs_band + fs_interior;
  errors.false_light = fl_band + fl_interior;
  errors.max_distance_px = std::sqrt(max_d2);
  if (errors.receiver_pixels > 0) {
    const double n = double(errors.receiver_pixels);
    errors.false_shadow_band = static_cast<double>(fs_band) / n;
    errors.false_shadow_interior = static_cast<double>(fs_interior) / n;
    errors.false_light_band = static_cast<double>(fl_band) / n;
    errors.false_light_interior = static_cast<double>(fl_interior) / n;
    errors.misclassified = static_cast<double>(errors.false_shadow + errors.false_light) / n;
  }
  return errors;
}

namespace {

// OpenImageIO's comparison, its PSNR made finite for identical images.
ImageErrors image_errors(const media::Difference &d) {
  ImageErrors errors;
  errors.mean = d.mean;
  errors.max = d.max;
  errors.psnr = std::isfinite(d.psnr) ? d.psnr : kIdenticalPsnrDb;
  errors.pixels_over_threshold = d.over_threshold;
  return errors;
}

}  // namespace

bool compare_images(const std::string &a, const std::string &b, const std::string &heat_map,
                    ImageErrors &errors, std::string &error) {
  const media::ImageFiles *files = media::image_files(error);
  if (files == nullptr) return false;
  media::FloatImage image_a, image_b;
  if (!read_image(*files, a, image_a, error) || !read_image(*files, b, image_b, error)) return false;
  if (image_a.width != image_b.width || image_a.height != image_b.height ||
      image_a.channels != image_b.channels) {
    error = "images differ in size: '" + a + "' is " + std::to_string(image_a.width) + "x" +
            std::to_string(image_a.height) + "x" + std::to_string(image_a.channels) + ", '" + b +
            "' is " + std::to_string(image_b.width) + "x" + std::to_string(image_b.height) + "x" +
            std::to_string(image_b.channels);
    return false;
  }
  errors = image_errors(files->compare(image_a, image_b, kFailThreshold));
  return heat_map.empty() || write_heat_map(*files, image_a, image_b, heat_map, error);
}

bool compare_rgb(const std::vector<std::uint8_t> &a, const std::vector<std::uint8_t> &b,
                 int width, int height, ImageErrors &errors, std::string &error) {
  const std::size_t bytes = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0)) * 3;
  if (bytes == 0 || a.size() != bytes || b.size() != bytes) {
    error = "cannot compare images of " + std::to_string(a.size()) + " and " +
            std::to_string(b.size()) + " bytes as " + std::to_string(width) + "x" +
            std::to_string(height) + " RGB";
    return false;
  }
  const media::ImageFiles *files = media::image_files(error);
  if (files == nullptr) return false;
  errors = image_errors(files->compare_rgb(a.data(), b.data(), width, height, kFailThreshold));
  return true;
}

bool read_mask(const std::string &path, std::vector<std::uint8_t> &mask, int &width, int &height,
               std::string &error, bool *black_and_white) {
  const media::ImageFiles *files = media::image_files(error);
  media::FloatImage image;
  if (files == nullptr || !read_image(*files, path, image, error)) return false;
  // Alpha is skipped when there are colour channels: an opaque RGBA mask would otherwise be all 1.
  const int alpha = image.channels > 1 ? image.alpha_channel : -1;
  const int nc = image.channels;
  const std::vector<float> &pixels = image.pixels;
  mask.assign(std::size_t(image.width) * image.height, 0);
  // Two levels: black (every colour channel 0) and one grey above half shared by all other
  // pixels. `render --mask` writes its white through the shim's gamma table as 254, `truth` 255.
  bool two_levels = true;
  float white = -1.0f;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    const float first = pixels[i * nc + (alpha == 0 ? 1 : 0)];
    for (int c = 0; c < nc; ++c) {
      if (c == alpha) continue;
      if (pixels[i * nc + c] > 0.5f) mask[i] = 1;
      if (pixels[i * nc + c] != first) two_levels = false;  // not grey
    }
    if (first == 0.0f) continue;
    if (first <= 0.5f || (white >= 0.0f && first != white)) two_levels = false;
    white = first;
  }
  if (black_and_white != nullptr) *black_and_white = two_levels;
  width = image.width;
  height = image.height;
  return true;
}

}  // namespace gs
