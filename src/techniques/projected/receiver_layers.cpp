// Receivers that hide part of a caster from the light, and those that hold a caster part between
// two of their layers (receiver_layers.h). Light clip space: the caster's edges sampled every few
// texels, each receiver's triangles sorted into a grid of the light's screen (NDC), and per
// sample the receiver surfaces on the light's ray through it, with their depth (w, metres along
// the light's axis) and whether they face the light.
#include "techniques/projected/receiver_layers.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace gs {
namespace {

constexpr int kLayerGrid = 32;              // cells a side of the light's screen, NDC [-1, 1]
constexpr float kSampleTexels = 4.0f;  // caster edges are sampled at least this often
constexpr int kMostSamplesPerEdge = 64;
// A texture coarser than this has its edges' samples split further, as if it were this size.
constexpr int kSampleViewSize = 256;

struct EdgeSample {
  glm::vec2 ndc;
  float w;  // light-view depth, metres
};

// A receiver vertex in the light's view; ndc and inverse_w are valid when w > 0.
struct LayerVertex {
  glm::vec2 ndc;
  float w;          // light clip w: metres along the light's axis
  float inverse_w;  // 1 / w: linear in NDC
};

struct LayerTriangle {
  glm::vec2 a;                 // NDC
  glm::vec2 to_b, to_c;        // b - a, c - a, NDC
  float area;                  // twice the signed NDC area, never near 0 (those are dropped)
  glm::vec2 low, high;         // NDC bounding box
  glm::vec3 inverse_w;         // 1 / w at a, b, c: linear in NDC
  bool faces_light = false;
  bool shaded = false;         // step 3 may shade it with the caster's shadow
  float nearest_w = 0.0f;      // the least of its vertices' w: no point of it is nearer
  std::size_t number = 0;      // in the receiver's mesh
};

// 1 / w interpolated with barycentric weights that are not negative and sum to 1 (both to a
// few float ulps) gives a w no less than the least vertex w times this: a sample this much
// nearer than every such triangle in its cell cannot be behind one (receiver_layers' skip).
constexpr float kInterpolatedWMargin = 1.0f - 1e-4f;

// Triangle indices per cell of the light's screen (kLayerGrid a side), in increasing order,
// each cell's run at items[start[cell]] up to items[start[cell + 1]].
struct LayerGrid {
  std::vector<std::size_t> start, items;
};

// Truncated, not floored: the two differ only below 0, which the clamp takes to cell 0 either way.
int layer_cell_of(float ndc) {
  return std::clamp(static_cast<int>((ndc + 1.0f) * 0.5f * kLayerGrid), 0, kLayerGrid - 1);
}

// Barycentric weights of p in the NDC triangle; false when outside.
inline bool layer_weights(const LayerTriangle &t, const glm::vec2 &p, glm::vec3 &l) {
  const glm::vec2 &e0 = t.to_b, &e1 = t.to_c;
  const glm::vec2 d = p - t.a;
  const float u = (d.x * e1.y - d.y * e1.x) / t.area, v = (e0.x * d.y - e0.y * d.x) / t.area;
  if (u < 0.0f || v < 0.0f || u + v > 1.0f) return false;
  l = {1.0f - u - v, u, v};
  return true;
}

// Buckets `list` by the cells its NDC boxes, clipped to the samples' box, touch.
void bucket_layer_triangles(const std::vector<LayerTriangle> &list, const glm::vec2 &sample_low,
                            const glm::vec2 &sample_high, LayerGrid &grid) {
  constexpr std::size_t kCellCount = kLayerGrid * kLayerGrid;
  grid.start.assign(kCellCount + 1, 0);
  auto for_each_cell = [&](const LayerTriangle &lt, auto &&visit) {
    const glm::vec2 t_low = glm::max(lt.low, sample_low), t_high = glm::min(lt.high, sample_high);
    for (int y = layer_cell_of(t_low.y); y <= layer_cell_of(t_high.y); ++y) {
      for (int x = layer_cell_of(t_low.x); x <= layer_cell_of(t_high.x); ++x) {
        visit(static_cast<std::size_t>(y * kLayerGrid + x));
      }
    }
  };
  for (const LayerTriangle &lt : list) {
    for_each_cell(lt, [&](std::size_t cell) { ++grid.start[cell + 1]; });
  }
  for (std::size_t cell = 0; cell < kCellCount; ++cell) grid.start[cell + 1] += grid.start[cell];
  grid.items.resize(grid.start.back());
  std::vector<std::size_t> next(grid.start.begin(), grid.start.end() - 1);
  for (std::size_t i = 0; i < list.size(); ++i) {
    for_each_cell(list[i], [&](std::size_t cell) { grid.items[next[cell]++] = i; });
  }
}

}  // namespace

ReceiverLayers receiver_layers(const Scene &scene, const FrameGeometry &frame, std::size_t caster,
                               const LightView &view,
                               const std::vector<PiercedReceiver> &pierced,
                               const std::optional<glm::vec4> &caster_plane) {
  ReceiverLayers layers;
  const SceneObject &object = scene.objects[caster];
  // A flat caster's receivers are clipped to the far side of its plane in step 3, which keeps
  // every nearer layer lit and every farther one in its shadow: no layer needs a mask.
  if (caster_plane) return layers;
  const glm::mat4 light_clip = view.projection * view.view;
  const Mesh &mesh = caster_mesh(object);
  std::vector<glm::vec4> clip(mesh.positions.size());
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (std::size_t i = 0; i < clip.size(); ++i) {
    const glm::vec4 world = object.model_to_world * glm::vec4(mesh.positions[i], 1.0f);
    low = glm::min(low, glm::vec3(world)), high = glm::max(high, glm::vec3(world));
    clip[i] = light_clip * world;
  }
  if (clip.empty()) return layers;
  // Depths closer than this to a receiver's surface touch it (a crate resting on a mound).
  const float tolerance = 1e-3f * glm::length(high - low);
  // Every vertex, and each edge's inside once, sampled along its light clip segment (linear
  // there) at least every kSampleTexels of the light's view.
  std::vector<EdgeSample> samples;
  glm::vec2 sample_low(INFINITY), sample_high(-INFINITY);
  float farthest_sample = 0.0f;
  auto add_sample = [&](const glm::vec4 &s) {
    if (s.w <= view.caster_front || std::abs(s.x) > s.w || std::abs(s.y) > s.w) return;
    samples.push_back({glm::vec2(s) / s.w, s.w});
    farthest_sample = std::max(farthest_sample, s.w);
    sample_low = glm::min(sample_low, samples.back().ndc);
    sample_high = glm::max(sample_high, samples.back().ndc);
  };
  for (const glm::vec4 &p : clip) add_sample(p);
  // Each edge once, as (lower vertex << 32 | higher vertex): sorted as the vertex pairs would be.
  std::vector<std::uint64_t> edges;
  edges.reserve(mesh.triangles.size() * 3);
  auto edge_key = [](unsigned a, unsigned b) {
    return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
  };
  for (const glm::uvec3 &t : mesh.triangles) {
    edges.push_back(edge_key(t.x, t.y));
    edges.push_back(edge_key(t.y, t.z));
    edges.push_back(edge_key(t.z, t.x));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const float texels_per_ndc = 0.5f * static_cast<float>(view.size);
  // A coarse texture's spacing (4 of its texels, 16 of a 256 view at 64) steps over a caster
  // part lying between two layers that a finer one finds (sunk-narrow-cones_17223, issue 14):
  // its spacing split `finer` times, which keeps its own samples (spacing the samples by the
  // finer view alone moves them, and lost such a part that the coarse spacing had found).
  const int finer = std::max(1, kSampleViewSize / std::max(view.size, 1));
  for (const std::uint64_t edge : edges) {
    const glm::vec4 &p = clip[edge >> 32], &q = clip[edge & 0xffffffffu];
    if (!(p.w > 0.0f && q.w > 0.0f)) continue;
    const float texels = glm::length(glm::vec2(p) / p.w - glm::vec2(q) / q.w) * texels_per_ndc;
    const int steps =
        std::clamp(static_cast<int>(std::ceil(texels / kSampleTexels)), 1, kMostSamplesPerEdge) *
        finer;
    for (int k = 1; k < steps; ++k) {
      add_sample(p + (q - p) * (static_cast<float>(k) / static_cast<float>(steps)));
    }
  }
  if (samples.empty()) return layers;
  // Step 3's cover of the texture (LightView::nearest, filled in step 1): per cell of 16 a side,
  // the nearest depth of every caster triangle whose bounding box touches it. A receiver
  // triangle wholly nearer the light than that in every cell it touches is never shaded with
  // this caster's shadow (receiver_coords.cpp), so what it hides needs no masking.
  constexpr int kCells = LightView::kCells;
  auto shade_cell = [](float ndc) {  // truncated as in layer_cell_of
    return std::clamp(static_cast<int>((ndc + 1.0f) * 0.5f * kCells), 0, kCells - 1);
  };
  std::vector<float> cell_nearest(kCells * kCells, INFINITY);
  for (const glm::uvec3 &t : mesh.triangles) {
    const glm::vec4 &a = clip[t.x], &b = clip[t.y], &c = clip[t.z];
    if (a.w <= 0.0f || b.w <= 0.0f || c.w <= 0.0f) continue;
    const glm::vec2 pa = glm::vec2(a) / a.w, pb = glm::vec2(b) / b.w, pc = glm::vec2(c) / c.w;
    const glm::vec2 t_low = glm::min(pa, glm::min(pb, pc)), t_high = glm::max(pa, glm::max(pb, pc));
    const float nearest = std::min(a.w, std::min(b.w, c.w));
    for (int y = shade_cell(t_low.y); y <= shade_cell(t_high.y); ++y) {
      for (int x = shade_cell(t_low.x); x <= shade_cell(t_high.x); ++x) {
        float &cell = cell_nearest[static_cast<std::size_t>(y * kCells + x)];
        cell = std::min(cell, nearest);
      }
    }
  }
  const float texel = 2.0f / static_cast<float>(view.size);  // NDC, bilinear reach

  std::vector<LayerTriangle> triangles, behind;
  std::vector<LayerVertex> receiver_view;
  LayerGrid grid;
  auto cell_at = [&](const glm::vec2 &ndc) {
    const std::size_t cell =
        static_cast<std::size_t>(layer_cell_of(ndc.y) * kLayerGrid + layer_cell_of(ndc.x));
    return std::make_pair(grid.items.data() + grid.start[cell],
                          grid.items.data() + grid.start[cell + 1]);
  };
  std::vector<float> cell_hiding;  // per grid cell, the nearest light-facing shaded triangle's w
  std::vector<const EdgeSample *> unresolved;  // outside and hidden, nothing lit behind found yet
  std::vector<std::size_t> fronts;  // a sample's light-facing shaded triangles in front of it
  for (std::size_t r = 0; r < frame.objects.size(); ++r) {
    const ProjectedObject &receiver = frame.objects[r];
    if (r == caster || !receiver.object->receives_shadow) continue;
    const auto known = std::find_if(pierced.begin(), pierced.end(),
                                    [r](const PiercedReceiver &p) { return p.receiver == r; });
    if (known != pierced.end() && known->planar) continue;  // clipped to its plane already
    triangles.clear();
    behind.clear();
    float nearest_hiding = INFINITY;  // the least w of a light-facing, shaded triangle
    // Each vertex's light clip position, and its NDC once for all the triangles sharing it.
    receiver_view.resize(receiver.world.size());
    for (std::size_t i = 0; i < receiver_view.size(); ++i) {
      const glm::vec4 c = light_clip * glm::vec4(receiver.world[i], 1.0f);
      LayerVertex &v = receiver_view[i];
      v.w = c.w;
      if (c.w > 0.0f) v.ndc = glm::vec2(c) / c.w, v.inverse_w = 1.0f / c.w;
    }
    for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
      const LayerVertex &va = receiver_view[t.x], &vb = receiver_view[t.y], &vc = receiver_view[t.z];
      if (va.w <= 0.0f || vb.w <= 0.0f || vc.w <= 0.0f) continue;  // reaches behind the light
      const glm::vec2 t_low = glm::min(va.ndc, glm::min(vb.ndc, vc.ndc));
      const glm::vec2 t_high = glm::max(va.ndc, glm::max(vb.ndc, vc.ndc));
      if (glm::any(glm::lessThan(t_high, sample_low)) || glm::any(glm::lessThan(sample_high, t_low)))
        continue;
      LayerTriangle lt;
      lt.a = va.ndc, lt.to_b = vb.ndc - va.ndc, lt.to_c = vc.ndc - va.ndc;
      lt.area = lt.to_b.x * lt.to_c.y - lt.to_b.y * lt.to_c.x;
      if (std::abs(lt.area) < 1e-12f) continue;  // no sample lies inside it
      lt.low = t_low, lt.high = t_high;
      lt.inverse_w = {va.inverse_w, vb.inverse_w, vc.inverse_w};
      const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
      lt.faces_light = glm::dot(glm::cross(b - a, c - a), view.position - a) > 0.0f;
      // Wholly behind every sample: it can only be a lit layer behind one (looked at below, if
      // some sample needs it).
      lt.nearest_w = std::min(va.w, std::min(vb.w, vc.w));
      lt.number = static_cast<std::size_t>(&t - receiver.object->mesh.triangles.data());
      if (lt.nearest_w > farthest_sample + tolerance) {
        if (lt.faces_light) behind.push_back(lt);
        continue;
      }
      const float farthest = std::max(va.w, std::max(vb.w, vc.w));
      for (int y = shade_cell(t_low.y - texel); y <= shade_cell(t_high.y + texel) && !lt.shaded; ++y) {
        for (int x = shade_cell(t_low.x - texel); x <= shade_cell(t_high.x + texel); ++x) {
          if (farthest > cell_nearest[static_cast<std::size_t>(y * kCells + x)]) {
            lt.shaded = true;
            break;
          }
        }
      }
      triangles.push_back(lt);
      if (lt.faces_light && lt.shaded) nearest_hiding = std::min(nearest_hiding, lt.nearest_w);
    }
    // A sample can only be hidden behind a light-facing, shaded triangle more than `tolerance`
    // nearer than it: per cell of the grid, the nearest such triangle's least w; a receiver
    // with none nearer than the farthest sample, and a sample with none in its cell nearer
    // than itself, are skipped (neither can give `hides` or `between`).
    if (!(nearest_hiding * kInterpolatedWMargin < farthest_sample - tolerance)) continue;
    bucket_layer_triangles(triangles, sample_low, sample_high, grid);
    cell_hiding.assign(grid.start.size() - 1, INFINITY);
    for (std::size_t cell = 0; cell + 1 < grid.start.size(); ++cell) {
      for (std::size_t k = grid.start[cell]; k < grid.start[cell + 1]; ++k) {
        const LayerTriangle &lt = triangles[grid.items[k]];
        if (lt.faces_light && lt.shaded) cell_hiding[cell] = std::min(cell_hiding[cell], lt.nearest_w);
      }
    }
    bool hides = false, between = false;
    unresolved.clear();
    // The receiver's light-facing triangles in front of a sample with a light-facing layer of
    // it behind (ReceiverLayers::over_buried), over all samples.
    std::vector<std::uint8_t> over_buried(receiver.object->mesh.triangles.size(), 0);
    bool any_over_buried = false;
    // Samples with light-facing triangles in front and none found behind yet, each with where
    // its triangles' numbers begin in unsure_numbers.
    std::vector<std::pair<const EdgeSample *, std::size_t>> unsure_fronts;
    std::vector<std::size_t> unsure_numbers;
    for (const EdgeSample &s : samples) {
      const std::size_t cell =
          static_cast<std::size_t>(layer_cell_of(s.ndc.y) * kLayerGrid + layer_cell_of(s.ndc.x));
      if (!(cell_hiding[cell] * kInterpolatedWMargin < s.w - tolerance)) continue;
      float nearest_front = -INFINITY;  // the receiver surface just in front of the sample
      bool front_faces_light = false, hidden = false, lit_behind = false;
      const auto [first, last] = cell_at(s.ndc);
      fronts.clear();
      for (const std::size_t *i = first; i != last; ++i) {
        const LayerTriangle &lt = triangles[*i];
        glm::vec3 l;
        if (!layer_weights(lt, s.ndc, l)) continue;
        const float w = 1.0f / glm::dot(l, lt.inverse_w);
        if (w < s.w - tolerance) {
          if (w > nearest_front) nearest_front = w, front_faces_light = lt.faces_light;
          hidden = hidden || (lt.faces_light && lt.shaded && w >= view.caster_front);
          if (lt.faces_light && lt.shaded) fronts.push_back(lt.number);
        } else if (w > s.w + tolerance) {
          lit_behind = lit_behind || lt.faces_light;
        }
      }
      // A sample outside the receiver (the surface just in front of it faces away from the
      // light) needs the mask. So does one inside it when the caster does not pass through the
      // receiver's surface (it lies buried whole in it, as a plate in a slab): the surface in
      // front of it, which step 3 shades, stays lit. A sample inside a receiver the caster
      // passes through is masked already (pierced_surfaces.cpp).
      const bool outside = hidden && !front_faces_light;
      const bool buried = hidden && front_faces_light && known == pierced.end();
      hides = hides || outside || buried;
      between = between || ((outside || buried) && lit_behind);
      if (lit_behind) {
        for (std::size_t number : fronts) over_buried[number] = 1;
        any_over_buried = any_over_buried || !fronts.empty();
      } else if (!fronts.empty()) {
        unsure_fronts.push_back({&s, unsure_numbers.size()});
        unsure_numbers.insert(unsure_numbers.end(), fronts.begin(), fronts.end());
      }
      if (outside || buried) unresolved.push_back(&s);
    }
    if (!behind.empty() && (!unsure_fronts.empty() || (!between && !unresolved.empty()))) {
      bucket_layer_triangles(behind, sample_low, sample_high, grid);
    }
    // A lit layer wholly behind every sample, behind a sample with triangles in front of it.
    for (std::size_t k = 0; k < unsure_fronts.size() && !behind.empty(); ++k) {
      const glm::vec2 &ndc = unsure_fronts[k].first->ndc;
      const auto [first, last] = cell_at(ndc);
      glm::vec3 l;
      if (std::none_of(first, last, [&](std::size_t i) { return layer_weights(behind[i], ndc, l); }))
        continue;
      const std::size_t end =
          k + 1 < unsure_fronts.size() ? unsure_fronts[k + 1].second : unsure_numbers.size();
      for (std::size_t j = unsure_fronts[k].second; j < end; ++j) over_buried[unsure_numbers[j]] = 1;
      any_over_buried = true;
    }
    if (!between && !unresolved.empty() && !behind.empty()) {
      for (const EdgeSample *s : unresolved) {
        const auto [first, last] = cell_at(s->ndc);
        for (const std::size_t *i = first; i != last && !between; ++i) {
          glm::vec3 l;
          if (layer_weights(behind[*i], s->ndc, l)) between = true;
        }
        if (between) break;
      }
    }
    if (hides) layers.hiding.push_back(r);
    if (between) layers.between.push_back(r);
    if (any_over_buried) layers.over_buried.emplace_back(r, std::move(over_buried));
  }
  return layers;
}

std::string receiver_layers_error(const Scene &scene, std::size_t light, std::size_t caster,
                                  std::size_t receiver) {
  return "light " + std::to_string(light) + " and '" + scene.objects[caster].name +
         "': part of the caster lies between two parts of '" + scene.objects[receiver].name +
         "' as the light sees them (the nearer part hides it, the farther is in its shadow), "
         "which one shadow texture cannot show; it casts no shadow on '" +
         scene.objects[receiver].name + "' from this light";
}

ReachedReceivers reached_receivers(const Scene &scene, const FrameGeometry &frame,
                                   std::size_t light, std::size_t caster, const LightView &view,
                                   const std::optional<glm::vec4> &caster_plane,
                                   std::vector<std::string> &errors) {
  ReachedReceivers reached;
  std::vector<PiercedReceiver> &pierced = reached.pierced;
  pierced = pierced_receivers(scene, frame, caster, scene.lights[light].position, caster_plane);
  reached.layers = receiver_layers(scene, frame, caster, view, pierced, caster_plane);
  for (std::size_t r : reached.layers.between) {
    if (scene.objects[r].casts_shadow) reached.refused.push_back(r);
  }
  for (std::size_t r : reached.layers.hiding) {
    if (std::none_of(pierced.begin(), pierced.end(),
                     [r](const PiercedReceiver &p) { return p.receiver == r; })) {
      PiercedReceiver masked;
      masked.receiver = r;
      masked.planar = false;
      masked.casts = true;
      masked.caster_crossing.assign(caster_mesh(scene.objects[caster]).triangles.size(), 0);
      pierced.push_back(std::move(masked));
    }
  }
  for (std::size_t r : reached.refused) {
    errors.push_back(receiver_layers_error(scene, light, caster, r));
    pierced.erase(std::remove_if(pierced.begin(), pierced.end(),
                                 [r](const PiercedReceiver &p) { return p.receiver == r; }),
                  pierced.end());
  }
  return reached;
}

}  // namespace gs
