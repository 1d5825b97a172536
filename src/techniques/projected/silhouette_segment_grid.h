// Internal to step 3 (receiver_coords.cpp): the silhouette segments' boxes in the shadow
// texture, bucketed so that each receiver polygon asks only the segments near it for the error
// along the shadow's edges (shadow_edge_error.h). Space: light screen, in texels.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace gs {

// The silhouette segments' boxes in the texture (light screen, texels; low x, low y, high x,
// high y), bucketed by a 16x16 grid of cells so that a receiver polygon tests only the segments
// in the cells its own box overlaps (a fighter's silhouette has hundreds of segments, and each
// of its receiver triangles asked every one). Boxes and cells are clamped to the texture's edge
// cells alike, so two boxes that overlap share a cell; a NaN box overlaps nothing.
class SegmentGrid {
 public:
  SegmentGrid(float texels, std::vector<glm::vec4> boxes)
      : cell_(texels / static_cast<float>(kSide)), boxes_(std::move(boxes)),
        cells_(static_cast<std::size_t>(kSide * kSide)), stamp_(boxes_.size(), 0) {
    for (std::size_t k = 0; k < boxes_.size(); ++k) {
      int x0, y0, x1, y1;
      if (!cell_range(boxes_[k], x0, y0, x1, y1)) continue;
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) cells_[static_cast<std::size_t>(y * kSide + x)].push_back(k);
      }
    }
  }

  // The segments whose boxes overlap [low, high], in increasing order (as a scan would list
  // them, so the error's sum adds them in the same order).
  void overlapping(const glm::vec2 &low, const glm::vec2 &high, std::vector<std::size_t> &out) {
    out.clear();
    const glm::vec4 query(low, high);
    int x0, y0, x1, y1;
    if (!cell_range(query, x0, y0, x1, y1)) return;
    ++query_;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        for (std::size_t k : cells_[static_cast<std::size_t>(y * kSide + x)]) {
          if (stamp_[k] == query_) continue;
          stamp_[k] = query_;
          const glm::vec4 &box = boxes_[k];
          if (box.x <= high.x && box.z >= low.x && box.y <= high.y && box.w >= low.y) out.push_back(k);
        }
      }
    }
    std::sort(out.begin(), out.end());
  }

 private:
  static constexpr int kSide = 16;
  bool cell_range(const glm::vec4 &box, int &x0, int &y0, int &x1, int &y1) const {
    if (std::isnan(box.x) || std::isnan(box.y) || std::isnan(box.z) || std::isnan(box.w)) return false;
    auto index = [&](float texels) {
      return static_cast<int>(std::clamp(std::floor(texels / cell_), 0.0f, kSide - 1.0f));
    };
    x0 = index(box.x), y0 = index(box.y), x1 = index(box.z), y1 = index(box.w);
    return true;
  }
  float cell_;
  std::vector<glm::vec4> boxes_;
  std::vector<std::vector<std::size_t>> cells_;
  std::vector<unsigned> stamp_;  // the last query that listed each segment
  unsigned query_ = 0;
};

}  // namespace gs
