// The budget of the error along a frame's shadow edges (shadow_edge_error.h): the screen
// pixels the error measure counts, found by covering each pixel centre that some object's
// camera-facing triangle holds with its corners snapped to 1/16 px as the Voodoo draws it
// (Glide screen, pixels); and the whole pixels 0.1% of them allows.
#include "techniques/texel_error/shadow_edge_error.h"

#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gs {
namespace {

// The screen's covered pixels as bits, a row of whole words per screen row (pixel x of row y at
// bit x % 64 of word y * words + x / 64; Glide screen, rows in y): a span sets its words, where
// a byte a pixel cost a fill call a span and a count over every pixel of the screen.
// kCounting: cover() keeps the count of covered pixels as it goes (running_count), for a caller
// that stops once enough are; else count() counts them once at the end.
template <bool kCounting>
class CoveredPixels {
 public:
  static constexpr bool kCountingAsItGoes = kCounting;
  CoveredPixels(int width, int height)
      : words_(static_cast<std::size_t>(std::max(width, 0) + 63) / 64),
        bits_(words_ * static_cast<std::size_t>(std::max(height, 0)), 0) {}
  // Pixels from <= x < to of row y (0 <= from < to <= width).
  void cover(int y, int from, int to) {
    std::uint64_t *row = bits_.data() + static_cast<std::size_t>(y) * words_;
    const int first = from / 64, last = (to - 1) / 64;
    const std::uint64_t head = ~std::uint64_t{0} << (from % 64);
    const std::uint64_t tail = ~std::uint64_t{0} >> (63 - (to - 1) % 64);
    if (first == last) {
      set(row[first], head & tail);
      return;
    }
    set(row[first], head);
    for (int word = first + 1; word < last; ++word) set(row[word], ~std::uint64_t{0});
    set(row[last], tail);
  }
  std::size_t count() const {
    std::size_t pixels = 0;
    for (const std::uint64_t word : bits_) {
      pixels += static_cast<std::size_t>(__builtin_popcountll(word));
    }
    return pixels;
  }
  std::size_t running_count() const { return covered_; }

 private:
  void set(std::uint64_t &word, std::uint64_t bits) {
    if (kCounting) covered_ += static_cast<std::size_t>(__builtin_popcountll(bits & ~word));
    word |= bits;
  }
  std::size_t words_;
  std::vector<std::uint64_t> bits_;
  std::size_t covered_ = 0;
};

// Where side p -> q of a polygon crosses the centre line of a row (y = centre, pixels), p and q
// on either side of it: the one expression both kinds of polygon below use, in the side's own
// direction, so that a triangle's spans are the general polygon's to the bit.
float crossing(const glm::vec2 &p, const glm::vec2 &q, float centre) {
  return p.x + (centre - p.y) * (q.x - p.x) / (q.y - p.y);
}

// The rows whose centre y + 0.5 lies in low < y + 0.5 <= high, within the screen's height:
// [first, past).
void rows_between(float low, float high, int height, int &first, int &past) {
  first = std::max(static_cast<int>(std::floor(low - 0.5f)) + 1, 0);
  past = std::min(static_cast<int>(std::floor(high - 0.5f)) + 1, height);
}

// std::ceil(pixels) as an int, for a value well inside int's range (a crossing of a polygon
// clipped to the screen): truncation leaves a positive fraction's value one short.
int ceil_to_int(float pixels) {
  const int truncated = static_cast<int>(pixels);
  return truncated + (static_cast<float>(truncated) < pixels ? 1 : 0);
}

// Covers the pixels of row y whose centre has left <= x + 0.5 < right (the row's crossings of the
// polygon's sides, pixels), within the width.
template <class Covered>
void cover_span(int y, float left, float right, int width, Covered &covered) {
  if (!(left < right)) return;
  const int from = std::max(ceil_to_int(left - 0.5f), 0);
  const int to = std::min(ceil_to_int(right - 0.5f), width);  // past the end
  if (from < to) covered.cover(y, from, to);
}

// Marks in `covered` the pixels whose centre (x + 0.5, y + 0.5) lies in the convex screen polygon
// `polygon` (pixels, already clipped to the screen). A centre on a level side counts where the
// shim's rasterizer draws it: on the polygon's bottom side (largest y), not its top (a floor's
// far triangles snapped to one row's centres). A row's centre line crosses the sides p -> q
// with p.y < centre <= q.y or q.y < centre <= p.y; its span runs between the crossings.
template <class Covered>
void cover_convex_polygon(const std::vector<glm::vec2> &polygon, int width, int height,
                          Covered &covered) {
  if (polygon.size() < 3) return;
  float low = INFINITY, high = -INFINITY;
  for (const glm::vec2 &p : polygon) low = std::min(low, p.y), high = std::max(high, p.y);
  int first_row, past_row;
  rows_between(low, high, height, first_row, past_row);
  if (polygon.size() == 3) {
    // A triangle (most polygons): its sides sorted by their lowest y, the longest in y crosses
    // every row and one of the other two each row, the upper one through the middle corner's y.
    const glm::vec2 *side[3][2];
    for (int i = 0; i < 3; ++i) side[i][0] = &polygon[i], side[i][1] = &polygon[(i + 1) % 3];
    const auto top = [&](int i) { return std::min(side[i][0]->y, side[i][1]->y); };
    const auto bottom = [&](int i) { return std::max(side[i][0]->y, side[i][1]->y); };
    int spanning = 0;  // the side from the lowest y to the highest
    for (int i = 1; i < 3; ++i) {
      if (top(i) == low && bottom(i) == high) spanning = i;
    }
    if (!(top(spanning) == low && bottom(spanning) == high)) return;  // no row: all level
    int upper = (spanning + 1) % 3, lower = (spanning + 2) % 3;
    if (top(lower) < top(upper)) std::swap(upper, lower);
    const float middle = bottom(upper);  // the middle corner's y
    for (int y = first_row; y < past_row; ++y) {
      const float centre = static_cast<float>(y) + 0.5f;
      const int other = centre <= middle ? upper : lower;
      const float a = crossing(*side[spanning][0], *side[spanning][1], centre);
      const float b = crossing(*side[other][0], *side[other][1], centre);
      cover_span(y, std::min(a, b), std::max(a, b), width, covered);
    }
    return;
  }
  for (int y = first_row; y < past_row; ++y) {
    const float centre = static_cast<float>(y) + 0.5f;
    float left = INFINITY, right = -INFINITY;  // where the row's centre line crosses the sides
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const glm::vec2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
      if ((p.y < centre) == (q.y < centre)) continue;
      const float x = crossing(p, q, centre);
      left = std::min(left, x), right = std::max(right, x);
    }
    cover_span(y, left, right, width, covered);
  }
}

// Covers in `drawn` the pixels receiver_screen_pixels counts, of every camera-facing triangle;
// or, when `drawn` counts as it goes (a bound), only of those wholly before the camera and
// within the guard band whose screen area (pixels, corners unsnapped) is at least least_area,
// stopping once `enough` are covered: a subset of the same triangles, covered the same way, so
// a subset of the same pixels.
template <class Covered>
void cover_receivers(const Scene &scene, const FrameGeometry &frame, float least_area,
                     std::size_t enough, Covered &drawn) {
  const int width = scene.width, height = scene.height;
  const float right = static_cast<float>(width), top = static_cast<float>(height);
  // The screen's sides as half-planes (x, y, 1) . side >= 0 (Glide screen, pixels).
  const glm::vec3 sides[4] = {{1, 0, 0}, {-1, 0, right}, {0, 1, 0}, {0, -1, top}};
  // Per pixel: some camera-facing triangle covers its centre. A pixel two objects cover (the
  // floor behind a wall) counts once, as the error measure counts the surface seen there.
  // Covered by the triangles snapped, as the frame draws them: the measure leaves out a pixel
  // the truth sees and the frame leaves as background (compare_masks' undrawn pixels: a floor
  // seen 7 cm above it, its far triangles thinner than the snap, planar19_camera_7cm_160x120:
  // 9 of 487). The pixels the snap adds beyond the exact outline (a centre within 1/32 px of
  // it) are counted too; covering the exact triangles as well to leave those out cost 8.5 M
  // instructions of the demo's shadowed frame and moved no budget of the project's scenes.
  std::vector<glm::vec2> polygon, clipped;
  std::vector<ClipVertex> camera_polygon, scratch;
  std::vector<GrVertex> screen;
  for (const ProjectedObject &object : frame.objects) {
    for (const glm::uvec3 &t : object.object->mesh.triangles) {
      const glm::vec3 &a = object.world[t.x], &b = object.world[t.y], &c = object.world[t.z];
      if (glm::dot(glm::cross(b - a, c - a), scene.camera.position - a) <= 0.0f) continue;
      const bool inside = (object.outside[t.x] | object.outside[t.y] | object.outside[t.z]) == 0;
      if constexpr (Covered::kCountingAsItGoes) {  // a bound
        if (!inside) continue;
        const GrVertex &p = object.screen[t.x], &q = object.screen[t.y], &r = object.screen[t.z];
        const float twice = (q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y);
        if (!(std::fabs(twice) >= 2.0f * least_area)) continue;
      }
      polygon.clear();
      if (inside) {
        polygon.resize(3);  // written in place: growing it call by call cost a call each
        const unsigned corner[3] = {t.x, t.y, t.z};
        for (int k = 0; k < 3; ++k) polygon[static_cast<std::size_t>(k)] = {object.screen[corner[k]].x, object.screen[corner[k]].y};
      } else {  // through the camera's near plane and guard band first
        camera_polygon = {{{}, a, {}}, {{}, b, {}}, {{}, c, {}}};
        project_camera_polygon(frame, scene, camera_polygon, scratch, screen);
        for (const GrVertex &v : screen) polygon.emplace_back(v.x, v.y);
      }
      // Wholly on the screen (most triangles): clipping would keep the polygon as it is.
      const bool on_screen = std::all_of(polygon.begin(), polygon.end(), [&](const glm::vec2 &p) {
        return p.x >= 0.0f && p.x <= right && p.y >= 0.0f && p.y <= top;
      });
      for (const glm::vec3 &side : sides) {  // Sutherland-Hodgman
        if (on_screen) break;
        clipped.clear();
        for (std::size_t i = 0; i < polygon.size(); ++i) {
          const glm::vec2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
          const float dp = glm::dot(side, glm::vec3(p, 1.0f)), dq = glm::dot(side, glm::vec3(q, 1.0f));
          if (dp >= 0.0f) clipped.push_back(p);
          if ((dp >= 0.0f) != (dq >= 0.0f)) clipped.push_back(p + (q - p) * (dp / (dp - dq)));
        }
        polygon.swap(clipped);
      }
      for (glm::vec2 &p : polygon) p = {snap_to_subpixel(p.x), snap_to_subpixel(p.y)};
      cover_convex_polygon(polygon, width, height, drawn);
      if constexpr (Covered::kCountingAsItGoes) {
        if (drawn.running_count() >= enough) return;
      }
    }
  }
}

}  // namespace

float receiver_screen_pixels(const Scene &scene, const FrameGeometry &frame) {
  CoveredPixels<false> drawn(scene.width, scene.height);
  cover_receivers(scene, frame, 0.0f, 0, drawn);
  return static_cast<float>(drawn.count());
}

float receiver_screen_pixels_at_least(const Scene &scene, const FrameGeometry &frame,
                                      float least_area, float enough) {
  CoveredPixels<true> drawn(scene.width, scene.height);
  // Never more than the screen holds (and so a size_t whatever `enough` is: infinity, NaN).
  const float screen = static_cast<float>(std::max(scene.width, 0)) * static_cast<float>(std::max(scene.height, 0));
  const auto target = static_cast<std::size_t>(enough > 0.0f ? std::min(std::ceil(enough), screen) : 0.0f);
  cover_receivers(scene, frame, least_area, target, drawn);
  return static_cast<float>(drawn.running_count());
}

float edge_error_budget(const Scene &scene, const FrameGeometry &frame) {
  // A pixel centre is on one side of a shadow's edge or the other: the measure counts whole
  // pixels, so a frame whose 0.1% is under one pixel may hold none.
  return std::floor(kEdgeErrorReceiverShare * receiver_screen_pixels(scene, frame));
}

}  // namespace gs
