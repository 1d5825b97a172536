// The caster's surface as the light sees it (caster_surface_from_light.h). Light clip space:
// the caster's triangles in NDC with 1/w at their corners, sorted into a grid of their NDC box;
// a receiver polygon is clipped to each face whose box meets its own, and the two depths are
// compared at the corners of what is left.
#include "techniques/projected/caster_surface_from_light.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace gs {
namespace {

// A receiver point is shadowed by a caster surface nearer the light than its own depth times
// (1 - kTouch): a foot standing on the caster (equal depths, up to float rounding of both
// planes' 1/w, a few 1e-7 of the depth) is not.
constexpr float kTouch = 1e-4f;

using PolygonCorner = CasterSurfaceFromLight::PolygonCorner;

// Sutherland-Hodgman: keeps the part of `polygon` where `edge` (a, b, NDC) has the face's
// inside on its left when `sign` is 1, on its right when -1.
void clip_to_edge(std::vector<PolygonCorner> &polygon, const glm::vec2 &a, const glm::vec2 &b,
                  float sign, std::vector<PolygonCorner> &scratch) {
  scratch.clear();
  const glm::vec2 along = b - a;
  auto side = [&](const glm::vec2 &p) {
    const glm::vec2 d = p - a;
    return sign * (along.x * d.y - along.y * d.x);
  };
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const PolygonCorner &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    const float sp = side(p.ndc), sq = side(q.ndc);
    if (sp >= 0.0f) scratch.push_back(p);
    if ((sp >= 0.0f) != (sq >= 0.0f)) {
      const float t = sp / (sp - sq);
      scratch.push_back({p.ndc + (q.ndc - p.ndc) * t, p.inverse_w + (q.inverse_w - p.inverse_w) * t});
    }
  }
  polygon.swap(scratch);
}

}  // namespace

CasterSurfaceFromLight::CasterSurfaceFromLight(const SceneObject &caster, const glm::mat4 &light_clip)
    : CasterSurfaceFromLight(caster_mesh(caster), caster.model_to_world, light_clip) {}

CasterSurfaceFromLight::CasterSurfaceFromLight(const Mesh &mesh, const glm::mat4 &model_to_world,
                                               const glm::mat4 &light_clip, float nearest_w) {
  std::vector<glm::vec4> clip(mesh.positions.size());
  std::vector<unsigned> outside(mesh.positions.size(), 0);  // as draw_mask_surface's flags
  for (std::size_t i = 0; i < clip.size(); ++i) {
    const glm::vec4 &p = clip[i] = light_clip * (model_to_world * glm::vec4(mesh.positions[i], 1.0f));
    if (nearest_w > 0.0f) {
      outside[i] = (p.x < -p.w) | (p.x > p.w) << 1 | (p.y < -p.w) << 2 | (p.y > p.w) << 3 |
                   (p.w < nearest_w) << 4 | (p.w <= 0.0f) << 5;
    } else if (!(p.w > 0.0f)) {
      usable_ = false;
    }
  }
  if (!usable_) return;
  faces_.reserve(mesh.triangles.size());
  for (const glm::uvec3 &t : mesh.triangles) {
    if ((outside[t.x] & outside[t.y] & outside[t.z] & 0x1F) != 0) continue;
    if (((outside[t.x] | outside[t.y] | outside[t.z]) & 0x20) != 0) continue;
    const glm::vec4 &a = clip[t.x], &b = clip[t.y], &c = clip[t.z];
    Face face;
    face.a = glm::vec2(a) / a.w;
    face.to_b = glm::vec2(b) / b.w - face.a, face.to_c = glm::vec2(c) / c.w - face.a;
    face.area = face.to_b.x * face.to_c.y - face.to_b.y * face.to_c.x;
    // Edge-on to the light: it covers no area of the light's view (nor any texel centre).
    if (!(std::abs(face.area) >= 1e-12f)) continue;
    face.inverse_w = {1.0f / a.w, 1.0f / b.w, 1.0f / c.w};
    face.low = glm::min(face.a, face.a + glm::min(face.to_b, face.to_c));
    face.high = glm::max(face.a, face.a + glm::max(face.to_b, face.to_c));
    face.largest_inverse_w = std::max({face.inverse_w.x, face.inverse_w.y, face.inverse_w.z});
    face.reach = std::max({std::abs(face.low.x), std::abs(face.low.y), std::abs(face.high.x),
                           std::abs(face.high.y)});
    face.slope = ((std::abs(face.to_c.x) + std::abs(face.to_c.y)) *
                      std::abs(face.inverse_w.y - face.inverse_w.x) +
                  (std::abs(face.to_b.x) + std::abs(face.to_b.y)) *
                      std::abs(face.inverse_w.z - face.inverse_w.x)) /
                 std::abs(face.area);
    const glm::dvec2 to_w(double(face.inverse_w.y) - face.inverse_w.x,
                          double(face.inverse_w.z) - face.inverse_w.x);
    const glm::dvec2 to_b(face.to_b), to_c(face.to_c);
    face.gradient = glm::dvec2(to_c.y * to_w.x - to_b.y * to_w.y, to_b.x * to_w.y - to_c.x * to_w.x) /
                    double(face.area);
    const glm::vec2 corners[3] = {face.a, face.a + face.to_b, face.a + face.to_c};
    const float sign = face.area > 0.0f ? 1.0f : -1.0f;
    for (int edge = 0; edge < 3; ++edge) {
      const glm::vec2 along = corners[(edge + 1) % 3] - corners[edge];
      face.edge_start[edge] = corners[edge];
      face.edge_normal[edge] = sign * glm::vec2(-along.y, along.x);
      face.edge_length[edge] = std::abs(along.x) + std::abs(along.y);
    }
    low_ = glm::min(low_, face.low), high_ = glm::max(high_, face.high);
    faces_.push_back(face);
  }
  for (int axis = 0; axis < 2; ++axis) {
    cell_side_[axis] = std::max(high_[axis] - low_[axis], 1e-12f) / kGrid;
  }
  // Each face's cells (first and last column, first and last row), found once for both passes.
  std::vector<glm::ivec4> spans(faces_.size());
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const Face &face = faces_[f];
    spans[f] = {cell_of(face.low.x, 0), cell_of(face.high.x, 0), cell_of(face.low.y, 1),
                cell_of(face.high.y, 1)};
  }
  auto each_cell = [&](const glm::ivec4 &span, auto &&visit) {
    for (int y = span.z; y <= span.w; ++y) {
      for (int x = span.x; x <= span.y; ++x) visit(static_cast<std::size_t>(y * kGrid + x));
    }
  };
  start_.assign(kGrid * kGrid + 1, 0);
  for (const glm::ivec4 &span : spans) each_cell(span, [&](std::size_t cell) { ++start_[cell + 1]; });
  for (std::size_t cell = 0; cell + 1 < start_.size(); ++cell) start_[cell + 1] += start_[cell];
  items_.resize(start_.back());
  std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    each_cell(spans[f], [&](std::size_t cell) { items_[next[cell]++] = f; });
  }
  stamp_.assign(faces_.size(), 0);
}

int CasterSurfaceFromLight::cell_of(float ndc, int axis) const {
  // Clamped, then truncated: the same cell as floored then clamped (they differ only below 0).
  const float cell = (ndc - low_[axis]) / cell_side_[axis];
  return static_cast<int>(std::clamp(cell, 0.0f, static_cast<float>(kGrid - 1)));
}

// Whether clipping polygon_ to `face` (below) could find a corner of their common part where
// the face is nearer the light; false only when it surely cannot, by two tests that clip
// nothing. Each keeps a margin of kSlack float roundings of the values it compares, more than
// the clipping's own rounding (a few per clip, three clips) can move them, so a face it skips
// is one the clipping would have found nothing on: the answer stays the same to the bit.
// - An edge of the face with every corner of the polygon outside it: the part is empty.
// - The face's plane (its 1 / w, affine in NDC, taken beyond the face too) not nearer than the
//   polygon at any of the polygon's corners: the nearness compared, face 1 / w (1 - kTouch) -
//   polygon 1 / w, is affine in (NDC, 1 / w), and every corner of the part is a blend of the
//   polygon's corners there, so it is at most its largest at them.
bool CasterSurfaceFromLight::face_can_shadow(const Face &face) const {
  constexpr float kSlack = 64.0f * std::numeric_limits<float>::epsilon();
  const float reach = polygon_reach_ + face.reach;  // NDC: bounds every coordinate compared
  const std::size_t count = polygon_.size();
  const PolygonCorner *polygon = polygon_.data();
  for (int edge = 0; edge < 3; ++edge) {
    const float margin = kSlack * face.edge_length[edge] * reach;
    if (!(margin < INFINITY)) return true;  // NaN or overflow: let the clipping answer
    const glm::vec2 &start = face.edge_start[edge], &normal = face.edge_normal[edge];
    std::size_t i = 0;
    while (i < count && glm::dot(normal, polygon[i].ndc - start) < -margin) ++i;
    if (i == count) return false;
  }
  const float margin = kSlack * (reach * face.slope + face.largest_inverse_w + polygon_inverse_w_);
  if (!(margin < INFINITY)) return true;
  for (std::size_t i = 0; i < count; ++i) {
    const double plane =
        face.inverse_w.x + glm::dot(face.gradient, glm::dvec2(polygon[i].ndc) - glm::dvec2(face.a));
    if (!(plane * (1.0 - kTouch) - polygon[i].inverse_w < -double(margin))) return true;
  }
  return false;
}

bool CasterSurfaceFromLight::may_shadow(const glm::vec4 *light_clip, std::size_t count) const {
  if (!usable_) return true;
  std::vector<PolygonCorner> &polygon = polygon_;
  polygon.clear();
  glm::vec2 low(INFINITY), high(-INFINITY);
  polygon_reach_ = 0.0f, polygon_inverse_w_ = 0.0f;
  for (std::size_t i = 0; i < count; ++i) {
    if (!(light_clip[i].w > 0.0f)) return true;
    polygon.push_back({glm::vec2(light_clip[i]) / light_clip[i].w, 1.0f / light_clip[i].w});
    low = glm::min(low, polygon.back().ndc), high = glm::max(high, polygon.back().ndc);
    polygon_reach_ = std::max({polygon_reach_, std::abs(polygon.back().ndc.x),
                               std::abs(polygon.back().ndc.y)});
    polygon_inverse_w_ = std::max(polygon_inverse_w_, polygon.back().inverse_w);
  }
  if (faces_.empty() || glm::any(glm::lessThan(high, low_)) || glm::any(glm::lessThan(high_, low))) {
    return false;
  }
  ++query_;
  std::vector<PolygonCorner> &part = part_, &scratch = scratch_;
  const int x0 = cell_of(low.x, 0), x1 = cell_of(high.x, 0);
  const int y0 = cell_of(low.y, 1), y1 = cell_of(high.y, 1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const auto cell = static_cast<std::size_t>(y * kGrid + x);
      for (std::size_t k = start_[cell]; k < start_[cell + 1]; ++k) {
        const std::size_t f = items_[k];
        if (stamp_[f] == query_) continue;
        stamp_[f] = query_;
        const Face &face = faces_[f];
        if (glm::any(glm::lessThan(high, face.low)) || glm::any(glm::lessThan(face.high, low))) continue;
        if (!face_can_shadow(face)) continue;
        // The polygon's part over the face (convex), then both depths at its corners.
        part = polygon;
        const float sign = face.area > 0.0f ? 1.0f : -1.0f;
        const glm::vec2 b = face.a + face.to_b, c = face.a + face.to_c;
        clip_to_edge(part, face.a, b, sign, scratch);
        clip_to_edge(part, b, c, sign, scratch);
        clip_to_edge(part, c, face.a, sign, scratch);
        for (const PolygonCorner &corner : part) {
          const glm::vec2 d = corner.ndc - face.a;
          const float u = (d.x * face.to_c.y - d.y * face.to_c.x) / face.area;
          const float v = (face.to_b.x * d.y - face.to_b.y * d.x) / face.area;
          const float face_inverse_w =
              glm::dot(glm::vec3(1.0f - u - v, u, v), face.inverse_w);
          // The face nearer than the polygon: w_face < w_polygon (1 - kTouch).
          if (face_inverse_w * (1.0f - kTouch) > corner.inverse_w) return true;
        }
      }
    }
  }
  return false;
}

bool CasterSurfaceFromLight::may_shadow_triangle(const SceneObject &receiver, std::size_t triangle,
                                                 const glm::vec4 (&corners)[3]) const {
  auto known = std::find_if(answers_.begin(), answers_.end(),
                            [&](const auto &entry) { return entry.first == &receiver; });
  if (known == answers_.end()) {
    answers_.emplace_back(&receiver, std::vector<signed char>(receiver.mesh.triangles.size(), -1));
    known = answers_.end() - 1;
  }
  signed char &answer = known->second[triangle];
  if (answer < 0) answer = may_shadow(corners, 3) ? 1 : 0;
  return answer != 0;
}

const CasterSurfaceFromLight &CasterSurfacesFromLight::at(const glm::mat4 &light_clip) {
  for (const auto &[matrix, surface] : built_) {
    if (std::memcmp(&matrix, &light_clip, sizeof matrix) == 0) return *surface;
  }
  built_.emplace_back(light_clip, std::make_unique<CasterSurfaceFromLight>(caster_, light_clip));
  return *built_.back().second;
}

const CasterSurfaceFromLight &CasterSurfacesFromLight::receiver_at(const SceneObject &receiver,
                                                                   const glm::mat4 &light_clip,
                                                                   float nearest_w) {
  for (const ReceiverSurface &built : receivers_) {
    if (built.receiver == &receiver &&
        std::memcmp(&built.light_clip, &light_clip, sizeof light_clip) == 0) {
      return *built.surface;
    }
  }
  receivers_.push_back({&receiver, light_clip,
                        std::make_unique<CasterSurfaceFromLight>(receiver.mesh, receiver.model_to_world,
                                                                 light_clip, nearest_w)});
  return *receivers_.back().surface;
}

}  // namespace gs
