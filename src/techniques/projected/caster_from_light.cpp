// Step 1 of the projected shadow texture: the caster drawn flat from the light (565 red 11110b on
// 0) into the back buffer or texture memory, clipped to its view's caster planes (and, for a
// curved receiver it reaches through, only where nearer the light than that receiver's surface:
// SurfaceMask), the cover of texture cells it touched (LightView::occupied, covered) and the
// cells its silhouette crosses. The cover is made before the drawing (cover_caster_from_light,
// mask_caster_cover, then draw_caster_from_light), so step 3 can run in between. Spaces: light
// view and light clip in; Glide screen (pixels, y down) of the light's size x size view out.
#include "techniques/projected/projected_shadow.h"

#include "techniques/projected/pierced_receivers.h"
#include "techniques/geometry/edge_mesh.h"

#include <glide_shim.h>
#include <glideutl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace gs {
namespace {

constexpr GrColor_t kShadowRedArgb = 0x00F00000u;  // red 240: the 565 red field 11110b

// Per vertex, an id its exactly equal positions share (model space; +0 and -0 are equal), so
// that vertices split for normals join; a non-finite position keeps an id of its own.
std::vector<unsigned> position_ids(const std::vector<glm::vec3> &positions) {
  std::vector<unsigned> order, ids(positions.size());
  for (unsigned i = 0; i < positions.size(); ++i) {
    const glm::vec3 &p = positions[i];
    ids[i] = i;
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) order.push_back(i);
  }
  std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
    const glm::vec3 &p = positions[a], &q = positions[b];
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  });
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (positions[order[k]] == positions[order[k - 1]]) ids[order[k]] = ids[order[k - 1]];
  }
  return ids;
}

// Per walk of a triangle's edge (triangle k's ab, bc, ca at 3k, 3k + 1, 3k + 2), whether the
// edge is on the caster's silhouette from the light: between a triangle facing the light and
// one facing away, or on one triangle only (an open mesh's rim). Edges are joined by their
// ends' positions (position_ids); facing is in light view space, with the light at the origin.
// One walk of each edge also has kTakenWalk set, so that an edge can be taken once: the first
// whose triangle faces the light (the first of a rim facing away), and a rim's walk (an edge
// with two ends apart walked by one triangle) kRimWalk. `closed` is
// is_closed_surface(mesh) from the same sorted walks (each welded edge walked as often each way
// by the triangles weld keeps), so the caster's edges are sorted once a view.
constexpr std::uint8_t kOnSilhouette = 1, kTakenWalk = 2, kRimWalk = 4;
std::vector<std::uint8_t> silhouette_walks(const Mesh &mesh, const std::vector<glm::vec4> &in_view,
                                           bool &closed) {
  const std::vector<unsigned> ids = position_ids(mesh.positions);
  struct EdgeWalk {
    std::uint64_t edge;  // lower id << 32 | higher id
    bool facing;
    int direction;  // +1 walked lower id -> higher, -1 the other way, 0 a triangle weld drops
    std::size_t walk;
  };
  // Filed under the edge's lower id (a counting sort), then each id's few walks sorted by edge.
  std::vector<std::size_t> bucket_start(ids.size() + 1, 0);
  for (const glm::uvec3 &t : mesh.triangles) {
    for (const auto &end : {std::pair(t.x, t.y), std::pair(t.y, t.z), std::pair(t.z, t.x)}) {
      ++bucket_start[std::min(ids[end.first], ids[end.second]) + 1];
    }
  }
  for (std::size_t id = 0; id < ids.size(); ++id) bucket_start[id + 1] += bucket_start[id];
  std::vector<EdgeWalk> walks(bucket_start.back());
  std::vector<std::size_t> next(bucket_start.begin(), bucket_start.end() - 1);
  std::size_t walk = 0;
  // weld (stencil_volume_geometry.cpp) refuses a mesh with a non-finite position and drops a
  // triangle with two corners at one position or a zero cross product (model space).
  closed = std::all_of(mesh.positions.begin(), mesh.positions.end(), [](const glm::vec3 &p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  });
  for (const glm::uvec3 &t : mesh.triangles) {
    const glm::vec3 a(in_view[t.x]), b(in_view[t.y]), c(in_view[t.z]);
    const bool facing = glm::dot(glm::cross(b - a, c - a), -a) > 0.0f;
    const glm::vec3 &p = mesh.positions[t.x], &q = mesh.positions[t.y], &r = mesh.positions[t.z];
    const bool welded = ids[t.x] != ids[t.y] && ids[t.y] != ids[t.z] && ids[t.z] != ids[t.x] &&
                        glm::cross(q - p, r - p) != glm::vec3(0.0f);
    for (const auto &end : {std::pair(t.x, t.y), std::pair(t.y, t.z), std::pair(t.z, t.x)}) {
      const std::uint64_t low = std::min(ids[end.first], ids[end.second]);
      const std::uint64_t high = std::max(ids[end.first], ids[end.second]);
      const int direction = !welded ? 0 : ids[end.first] < ids[end.second] ? 1 : -1;
      walks[next[low]++] = {low << 32 | high, facing, direction, walk++};
    }
  }
  for (std::size_t id = 0; id < ids.size(); ++id) {
    std::sort(walks.begin() + static_cast<std::ptrdiff_t>(bucket_start[id]),
              walks.begin() + static_cast<std::ptrdiff_t>(bucket_start[id + 1]),
              [](const EdgeWalk &x, const EdgeWalk &y) { return x.edge < y.edge; });
  }
  std::vector<std::uint8_t> silhouette(walks.size(), 0);
  for (std::size_t first = 0, end = 0; first < walks.size(); first = end) {
    int facing = 0, balance = 0;
    for (end = first; end < walks.size() && walks[end].edge == walks[first].edge; ++end) {
      facing += walks[end].facing;
      balance += walks[end].direction;
    }
    closed = closed && balance == 0;
    const int count = static_cast<int>(end - first);
    const bool on_silhouette = count == 1 || (facing > 0 && facing < count);
    if (!on_silhouette) continue;
    for (std::size_t k = first; k < end; ++k) silhouette[walks[k].walk] = kOnSilhouette;
    std::size_t taken = first;
    while (taken + 1 < end && !walks[taken].facing) ++taken;
    silhouette[walks[taken].walk] |= kTakenWalk;
    if (count == 1 && walks[first].edge >> 32 != (walks[first].edge & 0xFFFFFFFFu)) {
      silhouette[walks[first].walk] |= kRimWalk;
    }
  }
  return silhouette;
}

}  // namespace

bool LightView::covered_near(const glm::vec2 &low, const glm::vec2 &high, float reach) const {
  if (!(low.x <= high.x) || !(low.y <= high.y)) return true;  // not finite
  const float cell = static_cast<float>(size) / kFineCells;  // texels
  const int x0 = std::max(0, static_cast<int>(std::floor((low.x - reach) / cell)));
  const int y0 = std::max(0, static_cast<int>(std::floor((low.y - reach) / cell)));
  const int x1 = std::min(kFineCells - 1, static_cast<int>(std::floor((high.x + reach) / cell)));
  const int y1 = std::min(kFineCells - 1, static_cast<int>(std::floor((high.y + reach) / cell)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (covered[static_cast<std::size_t>(y * kFineCells + x)]) return true;
    }
  }
  return false;
}

// Step 1's CPU part: the direct-path note, the caster's light-screen triangles and the cells
// they cover (LightView::occupied, covered, silhouette).
CasterDraw cover_caster_from_light(const Scene &scene, std::size_t caster, LightView &view,
                                   const ProjectedShadowOptions &options) {
  const SceneObject &object = scene.objects[caster];
  view.direct_path = options.direct_path;
  if (!view.direct_path && (view.size > scene.width || view.size > scene.height)) {
    view.direct_path = true;
    view.note = "a " + std::to_string(view.size) + "x" + std::to_string(view.size) +
                " shadow texture does not fit in the " + std::to_string(scene.width) + "x" +
                std::to_string(scene.height) + " back buffer; step 1 rendered it into texture "
                "memory directly";
  }
  view.cut_faces = std::make_shared<std::optional<SurfaceCuts::Faces>>();  // for step 3
  CasterDraw draw;
  const glm::mat4 to_view = view.view * object.model_to_world;
  const glm::vec3 light_world = view.position;
  const Mesh &mesh = caster_mesh(object);
  std::vector<GrVertex> &screen = draw.vertices;
  screen.resize(mesh.positions.size());
  draw.light_w.resize(mesh.positions.size());
  draw.caster_clip.resize(mesh.positions.size());
  std::vector<float> depth(mesh.positions.size());  // light-view distance along the axis (w)
  std::vector<glm::vec4> in_view(mesh.positions.size());
  std::vector<bool> inside(mesh.positions.size(), true);
  for (std::size_t i = 0; i < screen.size(); ++i) {
    in_view[i] = to_view * glm::vec4(mesh.positions[i], 1.0f);
    for (const glm::vec4 &plane : view.caster_planes) {
      if (glm::dot(plane, in_view[i]) < 0.0f) inside[i] = false;
    }
    const glm::vec4 clip = draw.caster_clip[i] = view.projection * in_view[i];
    if (inside[i]) screen[i] = to_screen(clip, view.size, view.size);
    depth[i] = draw.light_w[i] = clip.w;
  }
  const float cell = static_cast<float>(view.size) / LightView::kCells;  // texels
  const float fine_cell = static_cast<float>(view.size) / LightView::kFineCells;  // texels
  auto cell_index = [&](float texels) {  // truncated as in LightView::fine_cell_of
    return std::clamp(static_cast<int>(texels / cell), 0, LightView::kCells - 1);
  };
  auto fine_index = [&](float texels) { return view.fine_cell_of(texels); };
  // Marks the cells a drawn triangle's bounding box covers, with its nearest depth.
  auto occupy = [&](const GrVertex *const *corners, std::size_t count, float nearest) {
    float x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (std::size_t k = 0; k < count; ++k) {
      x0 = std::min(x0, corners[k]->x), x1 = std::max(x1, corners[k]->x);
      y0 = std::min(y0, corners[k]->y), y1 = std::max(y1, corners[k]->y);
    }
    // Cell bounds once a box, not once a loop test.
    const int cx0 = cell_index(x0), cx1 = cell_index(x1);
    const int cy0 = cell_index(y0), cy1 = cell_index(y1);
    for (int cy = cy0; cy <= cy1; ++cy) {
      for (int cx = cx0; cx <= cx1; ++cx) {
        const auto cell_at = static_cast<std::size_t>(cy * LightView::kCells + cx);
        view.occupied[cell_at] = true;
        view.nearest[cell_at] = std::min(view.nearest[cell_at], nearest);
      }
    }
    const int fx0 = fine_index(x0), fx1 = fine_index(x1);
    const int fy0 = fine_index(y0), fy1 = fine_index(y1);
    for (int cy = fy0; cy <= fy1; ++cy) {
      for (int cx = fx0; cx <= fx1; ++cx) {
        view.covered[static_cast<std::size_t>(cy * LightView::kFineCells + cx)] = true;
      }
    }
  };
  // Marks the fine cells along a segment of the light's screen (texels) in view.silhouette.
  auto trace = [&](const GrVertex &a, const GrVertex &b) {
    const float cells = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)) / fine_cell;
    const int steps = std::min(4 * LightView::kFineCells, static_cast<int>(std::ceil(2.0f * cells)) + 1);
    for (int k = 0; k <= steps; ++k) {
      const float f = static_cast<float>(k) / static_cast<float>(steps);
      const int x = fine_index(a.x + (b.x - a.x) * f), y = fine_index(a.y + (b.y - a.y) * f);
      view.silhouette[static_cast<std::size_t>(y * LightView::kFineCells + x)] = true;
    }
  };
  // The caster's silhouette from the light (silhouette_walks), traced from the lower end of
  // each edge by model position.
  bool closed = false;
  const std::vector<std::uint8_t> silhouette = silhouette_walks(mesh, in_view, closed);
  // A closed caster's back faces lie inside its front faces' outline; an open one (a tube, a
  // sheet) may show the light only its back, and a closed one around the light nothing else, so
  // those are drawn from both sides.
  draw.closed = !view.surrounds_light && closed;
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const glm::uvec3 &t = mesh.triangles[k];
    const unsigned ends[3][2] = {{t.x, t.y}, {t.y, t.z}, {t.z, t.x}};
    for (int e = 0; e < 3; ++e) {
      const std::uint8_t walk = silhouette[3 * k + static_cast<std::size_t>(e)];
      if (!walk) continue;
      unsigned i = ends[e][0], j = ends[e][1];
      if (std::tie(mesh.positions[j].x, mesh.positions[j].y, mesh.positions[j].z) <
          std::tie(mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z)) {
        std::swap(i, j);
      }
      if (walk & kRimWalk) {  // the whole edge, whatever part of it the caster planes keep
        view.rims.emplace_back(glm::vec3(object.model_to_world * glm::vec4(mesh.positions[i], 1.0f)),
                               glm::vec3(object.model_to_world * glm::vec4(mesh.positions[j], 1.0f)));
      }
      // The part of the edge inside the caster planes (light view space, parametric clip).
      float from = 0.0f, to = 1.0f;
      for (const glm::vec4 &plane : view.caster_planes) {
        const float di = glm::dot(plane, in_view[i]), dj = glm::dot(plane, in_view[j]);
        if (di < 0.0f && dj < 0.0f) from = 1.0f, to = 0.0f;
        else if (di < 0.0f) from = std::max(from, di / (di - dj));
        else if (dj < 0.0f) to = std::min(to, di / (di - dj));
      }
      if (from >= to) continue;
      trace(to_screen(view.projection * (in_view[i] + (in_view[j] - in_view[i]) * from), view.size, view.size),
            to_screen(view.projection * (in_view[i] + (in_view[j] - in_view[i]) * to), view.size, view.size));
      if (!(walk & kTakenWalk)) continue;  // the edge's other walks trace the same cells
      const glm::vec3 world_i(object.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
      const glm::vec3 world_j(object.model_to_world * glm::vec4(mesh.positions[j], 1.0f));
      // The taken walk's triangle (world): its side towards the light, and its centre, which
      // the light sees on the shadow's side of the edge.
      const glm::vec3 a(object.model_to_world * glm::vec4(mesh.positions[t.x], 1.0f));
      const glm::vec3 b(object.model_to_world * glm::vec4(mesh.positions[t.y], 1.0f));
      const glm::vec3 c(object.model_to_world * glm::vec4(mesh.positions[t.z], 1.0f));
      const glm::vec3 face = glm::cross(b - a, c - a);
      view.silhouette_segments.push_back({glm::mix(world_i, world_j, from), glm::mix(world_i, world_j, to),
                                          glm::dot(face, light_world - a) < 0.0f ? -face : face,
                                          (a + b + c) / 3.0f});
    }
  }
  const glm::mat4 world_from_view = glm::inverse(view.view);
  std::vector<ClipVertex> polygon, scratch;
  std::vector<GrVertex> fan;
  std::vector<float> fan_w;
  std::vector<const GrVertex *> corners;
  for (const glm::uvec3 &t : mesh.triangles) {
    if (inside[t.x] && inside[t.y] && inside[t.z]) {
      draw.triangles.push_back(t);  // tiles cut the caster
      const GrVertex *const triangle[3] = {&screen[t.x], &screen[t.y], &screen[t.z]};
      occupy(triangle, 3, std::min({depth[t.x], depth[t.y], depth[t.z]}));
      continue;
    }
    // Partly outside the beam's view: only the part inside is drawn.
    polygon.clear();
    for (unsigned i : {t.x, t.y, t.z}) polygon.push_back({in_view[i], {}, {}});
    for (const glm::vec4 &plane : view.caster_planes) {
      clip_polygon(polygon, plane, scratch);
      if (polygon.size() < 3) break;
    }
    if (polygon.size() < 3) continue;
    fan.clear();
    fan_w.clear();
    corners.clear();
    float nearest = INFINITY;
    for (const ClipVertex &v : polygon) {
      const glm::vec4 clip = view.projection * v.clip;
      fan.push_back(to_screen(clip, view.size, view.size));
      fan_w.push_back(clip.w);
      nearest = std::min(nearest, clip.w);
    }
    for (const GrVertex &v : fan) corners.push_back(&v);
    // The cut by a pierced receiver's plane bounds the shadow on that receiver (the cuts by the
    // view's border do not: the beam bounds the shadow there, step 3).
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const glm::vec4 &p = polygon[k].clip, &q = polygon[(k + 1) % polygon.size()].clip;
      for (const glm::vec4 &plane : view.edge_planes) {
        const float scale = 1e-4f * (glm::length(glm::vec3(p)) + glm::length(glm::vec3(q)));
        if (std::abs(glm::dot(plane, p)) <= scale && std::abs(glm::dot(plane, q)) <= scale) {
          trace(fan[k], fan[(k + 1) % fan.size()]);
          // The cut lies in the receiver's plane; no face or side of it is known.
          view.silhouette_segments.push_back(
              {glm::vec3(world_from_view * p), glm::vec3(world_from_view * q), glm::vec3(0.0f),
               glm::vec3(world_from_view * p)});
        }
      }
    }
    occupy(corners.data(), corners.size(), nearest);
    // Drawn as a fan of its first vertex, after the caster's own vertices in draw.vertices.
    const auto first = static_cast<unsigned>(screen.size());
    screen.insert(screen.end(), fan.begin(), fan.end());
    draw.light_w.insert(draw.light_w.end(), fan_w.begin(), fan_w.end());
    for (unsigned i = 2; i < fan.size(); ++i) draw.triangles.emplace_back(first, first + i - 1, first + i);
  }
  return draw;
}

void mask_caster_cover(const Scene &scene, std::size_t caster, LightView &view,
                       const SurfaceMask &mask, CasterDraw &draw) {
  // Every vertex takes its W from depth_oow (the mask surface's depth, pierced_surfaces.cpp).
  for (std::size_t i = 0; i < draw.vertices.size(); ++i) {
    draw.vertices[i].oow = depth_oow(view, draw.light_w[i]);
  }
  const Mesh &mesh = caster_mesh(scene.objects[caster]);
  auto fine_index = [&](float texels) { return view.fine_cell_of(texels); };
  // The caster's cut by the receiver's surface runs through its triangles that pass through
  // it: the fine cells of their bounding boxes join the silhouette.
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    if (!(*mask.caster_crossing)[k]) continue;
    const glm::uvec3 &t = mesh.triangles[k];
    glm::vec2 low(INFINITY), high(-INFINITY);
    for (unsigned i : {t.x, t.y, t.z}) {
      const glm::vec4 &clip = draw.caster_clip[i];
      if (!(clip.w > 0.0f)) continue;
      const GrVertex v = to_screen(clip, view.size, view.size);
      low = glm::min(low, glm::vec2(v.x, v.y)), high = glm::max(high, glm::vec2(v.x, v.y));
    }
    if (!(low.x <= high.x)) continue;
    const int x0 = fine_index(low.x), x1 = fine_index(high.x);
    const int y0 = fine_index(low.y), y1 = fine_index(high.y);
    for (int cy = y0; cy <= y1; ++cy) {
      for (int cx = x0; cx <= x1; ++cx) {
        view.silhouette[static_cast<std::size_t>(cy * LightView::kFineCells + cx)] = true;
      }
    }
  }
}

// Step 1's drawing: the flat render of `draw` (cover_caster_from_light's, for the same view and
// mask) into the back buffer's corner (the rest of the back buffer cleared) or texture memory.
// The LFB path leaves the clip window on the corner; draw_caster_from_light puts it back.
void draw_caster_flat(LightView &view, FxU32 texture_address, const SurfaceMask *mask,
                      const CasterDraw &draw) {
  // The flat render: 565 red 11110b on 0, no depth test (but a SurfaceMask's), back faces culled
  // (closed casters).
  if (view.direct_path && !glideShimRenderToTexture(GR_TMU0, texture_address, shadow_lod(view.size))) {
    view.usable = false;
    view.problem = std::string("step 1 cannot render into texture memory: ") +
                   glideShimGetLastErrorMessage();
    return;
  }
  const FxU32 side = static_cast<FxU32>(view.size);
  // The clear, colour to 0 (and depth to the farthest W for a SurfaceMask), of the size x size
  // region only (Glide screen, the target's top left), as a Voodoo clears the clip window: the
  // shim copies a clipped clear's words from a side buffer (clipped_clear.cpp), where a clear of
  // the whole 640x480 back buffer filled every tile of it before the read-back.
  grClipWindow(0, 0, side, side);
  grDepthBufferMode(mask ? GR_DEPTHBUFFER_WBUFFER : GR_DEPTHBUFFER_DISABLE);
  grDepthMask(mask ? FXTRUE : FXFALSE);
  grDitherMode(GR_DITHER_DISABLE);  // a dithered 240 would not always be 11110b
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  grCullMode(draw.closed ? GR_CULL_POSITIVE : GR_CULL_DISABLE);
  // A farthest-surface mask (SurfaceMask::farthest) keeps the greatest W its surface draws, so
  // its clear is the nearest.
  grBufferClear(0, 0, mask && mask->farthest ? GR_WDEPTHVALUE_NEAREST : GR_WDEPTHVALUE_FARTHEST);
  if (mask) {
    // The caster only where it is nearer.
    draw_mask_surface(view, *mask->receiver, mask->farthest, mask->triangles);
    grCullMode(draw.closed ? GR_CULL_POSITIVE : GR_CULL_DISABLE);  // the mask's strips draw unculled
  }
  grDepthMask(FXFALSE);
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grConstantColorValue(kShadowRedArgb);
  for (const glm::uvec3 &t : draw.triangles) {
    guDrawTriangleWithClip(&draw.vertices[t.x], &draw.vertices[t.y], &draw.vertices[t.z]);
  }
  if (mask) grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
  if (view.direct_path) glideShimRenderToFrameBuffer();
}

void draw_caster_from_light(const Scene &scene, LightView &view, FxU32 texture_address,
                            const SurfaceMask *mask, const CasterDraw &draw) {
  draw_caster_flat(view, texture_address, mask, draw);
  grClipWindow(0, 0, static_cast<FxU32>(scene.width), static_cast<FxU32>(scene.height));
}

void render_caster_from_light(const Scene &scene, std::size_t caster, LightView &view,
                              const ProjectedShadowOptions &options, FxU32 texture_address,
                              const SurfaceMask *mask) {
  CasterDraw draw = cover_caster_from_light(scene, caster, view, options);
  if (mask) mask_caster_cover(scene, caster, view, *mask, draw);
  draw_caster_from_light(scene, view, texture_address, mask, draw);
}

}  // namespace gs
