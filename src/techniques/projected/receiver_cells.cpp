// Which receiver polygons can take the caster's shadow or its edge (receiver_cells.h), and the
// pixel centres the snap takes from thin ones. Spaces: light clip in; light screen texels and
// the texture's cells between; world planes out; Glide screen (pixels) for the snap.
#include "techniques/projected/receiver_cells.h"

#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>

namespace gs {
namespace {

// How far beyond a receiver polygon's texel box the texture can reach it (texels): bilinear
// filtering reads texels whose centres lie less than one texel from the sample, and the half
// texel more absorbs the shim's 1/16 snapping of the caster's vertices in step 1 and of (s, t)
// in step 5 (a miss here would change bytes; a spare cell only costs its drawing).
constexpr float kReachTexels = 1.5f;

}  // namespace

void texel_box(const LightView &view, const glm::vec4 *light_clip, std::size_t count,
               glm::vec2 &low, glm::vec2 &high) {
  low = glm::vec2(INFINITY), high = glm::vec2(-INFINITY);
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec2 uv = (glm::vec2(light_clip[i].x, -light_clip[i].y) / light_clip[i].w * 0.5f +
                          0.5f) * static_cast<float>(view.size);  // texels
    low = glm::min(low, uv);
    high = glm::max(high, uv);
  }
}

bool sees_caster(const LightView &view, const glm::vec4 *light_clip, std::size_t count) {
  glm::vec2 low, high;
  texel_box(view, light_clip, count, low, high);
  float farthest = 0.0f;
  for (std::size_t i = 0; i < count; ++i) farthest = std::max(farthest, light_clip[i].w);
  const float cell = static_cast<float>(view.size) / LightView::kCells;
  const int x0 = std::max(0, static_cast<int>(std::floor((low.x - 1.0f) / cell)));
  const int y0 = std::max(0, static_cast<int>(std::floor((low.y - 1.0f) / cell)));
  const int x1 = std::min(LightView::kCells - 1, static_cast<int>(std::floor((high.x + 1.0f) / cell)));
  const int y1 = std::min(LightView::kCells - 1, static_cast<int>(std::floor((high.y + 1.0f) / cell)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const auto index = static_cast<std::size_t>(y * LightView::kCells + x);
      if (view.occupied[index] && farthest > view.nearest[index]) return true;
    }
  }
  return false;
}

bool reaches_covered_cell(const LightView &view, const glm::vec4 *light_clip, std::size_t count) {
  glm::vec2 low, high;
  texel_box(view, light_clip, count, low, high);
  return view.covered_near(low, high, kReachTexels);
}

namespace {

float cross(const glm::vec2 &a, const glm::vec2 &b, const glm::vec2 &p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// A receiver triangle's screen corners as they are (pixels).
struct ScreenCorners {
  glm::vec2 exact[3];
  float area = 0.0f;  // twice the signed area
  int longest = 0;    // its longest side, exact[longest] -> exact[(longest + 1) % 3]
  float longest_squared = 0.0f;
  explicit ScreenCorners(const GrVertex *v) {
    for (int k = 0; k < 3; ++k) exact[k] = {v[k].x, v[k].y};
    area = cross(exact[0], exact[1], exact[2]);
    for (int k = 0; k < 3; ++k) {
      const glm::vec2 side = exact[(k + 1) % 3] - exact[k];
      const float squared = glm::dot(side, side);
      if (squared > longest_squared) longest_squared = squared, longest = k;
    }
  }
  // Its least height under 1/16 px (area / longest side, compared squared).
  bool thin() const {
    constexpr float kSnap = 1.0f / 16.0f;  // pixels
    return area * area < kSnap * kSnap * longest_squared;
  }
};

// The same triangle as the Voodoo snaps its corners (pixels).
struct SnappedCorners {
  glm::vec2 snapped[3];
  bool drawn = false;  // a snapped area, wound as the exact triangle
  float snapped_area = 0.0f;  // twice the signed area
  explicit SnappedCorners(const ScreenCorners &corners) {
    for (int k = 0; k < 3; ++k) {
      snapped[k] = {snap_to_subpixel(corners.exact[k].x), snap_to_subpixel(corners.exact[k].y)};
    }
    snapped_area = cross(snapped[0], snapped[1], snapped[2]);
    drawn = snapped_area != 0.0f && (snapped_area > 0.0f) == (corners.area > 0.0f);
  }
  // The snapped triangle holds `centre` strictly inside, wound as the exact one.
  bool holds(const glm::vec2 &centre) const {
    if (!drawn) return false;
    for (int k = 0; k < 3; ++k) {
      if (!(cross(snapped[(k + 1) % 3], snapped[(k + 2) % 3], centre) * snapped_area > 0.0f)) {
        return false;
      }
    }
    return true;
  }
};

// Of row `y`'s columns x0..x1 (the box of a triangle thinner than the snap, Glide screen), those
// whose centre may pass its barycentric test, [from, to]: within a pixel of its longest side's
// line, and a column more each way. A centre the test passes lies within the triangle's height
// (under 1/16 px) of that line, or beyond it by the test's rounding: about 1e-6 of its distance
// to the corners, under 0.05 px with the corners in the guard band (8 screens each way) of a
// 1600x1200 screen. Where that side is close to level over the box, the whole row.
void columns_near_longest_side(const ScreenCorners &corners, int y, int x0, int x1, int &from,
                               int &to) {
  constexpr float kBand = 1.0f;  // pixels from the line
  from = x0, to = x1;
  const glm::vec2 &a = corners.exact[corners.longest];
  const glm::vec2 side = corners.exact[(corners.longest + 1) % 3] - a;
  // Half the band's width along the row (pixels): infinite for a level side.
  const float half = kBand * std::sqrt(corners.longest_squared) / std::abs(side.y);
  if (!(half < static_cast<float>(x1 - x0 + 2))) return;
  const float centre = static_cast<float>(y) + 0.5f;
  const float middle = a.x + side.x * (centre - a.y) / side.y;  // where the line crosses the row
  // The band's ends kept to a column beyond the box, so that they convert to int.
  const float left = std::max(middle - half, static_cast<float>(x0) - 1.0f);
  const float right = std::min(middle + half, static_cast<float>(x1) + 1.0f);
  from = std::max(x0, static_cast<int>(std::floor(left - 0.5f)) - 1);
  to = std::min(x1, static_cast<int>(std::ceil(right - 0.5f)) + 1);
}

}  // namespace

int centres_lost_to_snap(const LightView &view, const std::vector<ShadowTriangle> &triangles,
                         bool projective, int width, int height) {
  std::vector<glm::vec2> lost;  // the centres, Glide screen pixels
  std::vector<ScreenCorners> thick;
  for (const ShadowTriangle &triangle : triangles) {
    if (!triangle.reaches_caster) continue;
    const ScreenCorners corners(triangle.v);
    if (corners.area == 0.0f) continue;  // seen edge-on: it holds no centre to lose
    if (!corners.thin()) {
      thick.push_back(corners);
      continue;
    }
    const SnappedCorners snapped(corners);
    const glm::vec2 low = glm::min(corners.exact[0], glm::min(corners.exact[1], corners.exact[2]));
    const glm::vec2 high = glm::max(corners.exact[0], glm::max(corners.exact[1], corners.exact[2]));
    const int x0 = std::max(static_cast<int>(std::ceil(low.x - 0.5f)), 0);
    const int x1 = std::min(static_cast<int>(std::floor(high.x - 0.5f)), width - 1);
    const int y0 = std::max(static_cast<int>(std::ceil(low.y - 0.5f)), 0);
    const int y1 = std::min(static_cast<int>(std::floor(high.y - 0.5f)), height - 1);
    if (x0 > x1) continue;
    for (int y = y0; y <= y1; ++y) {
      int from, to;
      columns_near_longest_side(corners, y, x0, x1, from, to);
      for (int x = from; x <= to; ++x) {
        const glm::vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        float w[3];  // screen barycentric weights in the exact triangle
        for (int k = 0; k < 3; ++k) {
          w[k] = cross(corners.exact[(k + 1) % 3], corners.exact[(k + 2) % 3], centre) / corners.area;
        }
        if (w[0] < 0.0f || w[1] < 0.0f || w[2] < 0.0f || snapped.holds(centre)) continue;
        // Its (s, t) there (Glide texture units, 256 across), as step 5 would divide them.
        const GrVertex *v = triangle.v;
        float s = 0.0f, t = 0.0f, q = 0.0f;
        for (int k = 0; k < 3; ++k) {
          s += w[k] * v[k].tmuvtx[0].sow, t += w[k] * v[k].tmuvtx[0].tow;
          q += w[k] * (projective ? v[k].tmuvtx[0].oow : v[k].oow);
        }
        const glm::vec2 texel = glm::vec2(s, t) / q * (static_cast<float>(view.size) / 256.0f);
        if (view.covered_near(texel, texel, kReachTexels)) lost.push_back(centre);
      }
    }
  }
  if (lost.empty()) return 0;
  // A centre that a triangle as thick as the snap draws takes that triangle's own (s, t),
  // moved by no more than 1/32 px spans there: not lost.
  std::vector<SnappedCorners> drawn;
  drawn.reserve(thick.size());
  for (const ScreenCorners &corners : thick) drawn.emplace_back(corners);
  int count = 0;
  for (const glm::vec2 &centre : lost) {
    count += std::none_of(drawn.begin(), drawn.end(),
                          [&](const SnappedCorners &t) { return t.holds(centre); });
  }
  return count;
}

bool edge_rectangle(const LightView &view, const SilhouetteRows &rows, const glm::vec4 *light_clip,
                    std::size_t count, const glm::mat4 &world_to_light_clip,
                    std::vector<glm::vec4> &planes) {
  glm::vec2 low, high;
  texel_box(view, light_clip, count, low, high);
  auto index = [&](float texels) { return view.fine_cell_of(texels); };
  int x0 = LightView::kFineCells, y0 = LightView::kFineCells, x1 = -1, y1 = -1;
  const int box_x0 = index(low.x - kReachTexels), box_x1 = index(high.x + kReachTexels);
  for (int y = index(low.y - kReachTexels); y <= index(high.y + kReachTexels); ++y) {
    const int first = rows.next(y, box_x0);
    if (first > box_x1) continue;  // no silhouette cell in the box on this row
    const int last = rows.previous(y, box_x1);
    x0 = std::min(x0, first), x1 = std::max(x1, last), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  if (x1 < 0) return false;
  // Light NDC of the rectangle's sides, a texel wider (bilinear's reach; rows run down, y up).
  const float ndc_cell = 2.0f / LightView::kFineCells, texel = 2.0f / static_cast<float>(view.size);
  auto at = [&](int cells) { return static_cast<float>(cells) * ndc_cell; };
  const float left = -1.0f + at(x0) - texel, right = -1.0f + at(x1 + 1) + texel;
  const float top = 1.0f - at(y0) + texel, bottom = 1.0f - at(y1 + 1) - texel;
  const glm::mat4 to_world_planes = glm::transpose(world_to_light_clip);  // clip plane -> world
  for (const glm::vec4 &side : {glm::vec4(1, 0, 0, -left), glm::vec4(-1, 0, 0, right),
                                glm::vec4(0, 1, 0, -bottom), glm::vec4(0, -1, 0, top)}) {
    planes.push_back(to_world_planes * side);
  }
  return true;
}

}  // namespace gs
