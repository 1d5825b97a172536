// Step 3: the receivers' (s, t) from the light's view, and which receiver triangles can be in
// the caster's shadow (Listing 2's flags, the beam, the texture's cells: receiver_cells.h), and how many
// screen pixels a texel spans where its edge can fall (texel_footprint.h). Spaces: world
// and light view / light clip in; camera Glide screen vertices (pixels, y down) out, with (s, t)
// in Glide texture units (0..256 across the shadow texture) as sow, tow over their divisor.
#include "techniques/projected/projected_shadow.h"

#include "techniques/projected/caster_surface_from_light.h"
#include "techniques/projected/hidden_layers.h"
#include "techniques/projected/pierced_receivers.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/projected/receiver_cells.h"
#include "techniques/projected/receiver_depth_planes.h"
#include "techniques/projected/silhouette_segment_grid.h"
#include "techniques/texel_error/surface_cuts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace gs {
namespace {

// (s, t) numerators and divisor of a world point for step 5, in Glide texture units;
// `light_clip` is view.projection * view.view, made once per receiver pass.
glm::vec3 shadow_stq(const glm::mat4 &light_clip, const glm::vec3 &world) {
  const glm::vec4 clip = light_clip * glm::vec4(world, 1.0f);
  return {(0.5f * clip.x + 0.5f * clip.w) * 256.0f, (0.5f * clip.w - 0.5f * clip.y) * 256.0f,
          clip.w};
}

float shadow_alpha(const SpotLight &light, const LightView &view, const glm::vec3 &world,
                   ShadowAlpha mode) {
  float alpha = light.shadow_strength * 255.0f;
  if (mode == ShadowAlpha::Distance) {
    // Fainter the farther the receiver is behind the caster, as a wider penumbra would be.
    const float distance = glm::length(world - view.position);
    alpha *= std::clamp(view.caster_distance / std::max(distance, 1e-3f), 0.0f, 1.0f);
  }
  return alpha;
}

// Fills the texture fields of a camera-screen vertex for the world point it stands for.
void set_texture_fields(GrVertex &v, const LightView &view, const glm::mat4 &light_clip,
                        const SpotLight &light, const glm::vec3 &world,
                        const ProjectedShadowOptions &options) {
  const glm::vec3 stq = shadow_stq(light_clip, world);
  if (options.projective) {
    // The hardware divides per pixel by tmuvtx[0].oow (GR_STWHINT_W_DIFF_TMU0).
    v.tmuvtx[0].sow = stq.x * v.oow;
    v.tmuvtx[0].tow = stq.y * v.oow;
    v.tmuvtx[0].oow = stq.z * v.oow;
  } else {
    // Listing 3: (s, t) divided per vertex, interpolated with the camera's perspective only.
    v.tmuvtx[0].sow = stq.x / stq.z * v.oow;
    v.tmuvtx[0].tow = stq.y / stq.z * v.oow;
  }
  v.a = shadow_alpha(light, view, world, options.alpha);
}

// Where the caster's shadow can fall, as world-space planes (texel_footprint.h): beyond the
// caster's front and inside the camera's view. edge_rectangle adds each receiver polygon's own
// bound in the texture.
FootprintSpace footprint_space(const Scene &scene, const FrameGeometry &frame,
                               const LightView &view) {
  FootprintSpace space;
  space.light_clip = view.projection * view.view;
  space.texels = static_cast<float>(view.size);
  space.camera_clip = frame.view_projection;
  space.pixels = glm::vec2(static_cast<float>(scene.width), static_cast<float>(scene.height));
  space.planes.push_back(glm::transpose(view.view) * glm::vec4(0.0f, 0.0f, -1.0f, -view.caster_front));
  const glm::mat4 camera_planes = glm::transpose(frame.view_projection);
  for (const glm::vec4 &side : {glm::vec4(1, 0, 0, 1), glm::vec4(-1, 0, 0, 1), glm::vec4(0, 1, 0, 1),
                                glm::vec4(0, -1, 0, 1), glm::vec4(0, 0, 1, 1)}) {
    space.planes.push_back(camera_planes * side);
  }
  return space;
}

}  // namespace

ReceiverCoords compute_receiver_coords(const Scene &scene, const FrameGeometry &frame,
                                       std::size_t caster, const SpotLight &light,
                                       const LightView &view, const ProjectedShadowOptions &options,
                                       const std::vector<bool> *receivers,
                                       const std::vector<signed char> *depth_bands,
                                       float caster_back, CasterSurfacesFromLight *surfaces,
                                       const std::vector<std::uint8_t> *hidden_classes,
                                       const std::vector<std::uint8_t> *over_buried,
                                       const std::optional<glm::vec4> *caster_plane) {
  ReceiverCoords coords;
  const glm::mat4 light_clip = view.projection * view.view;
  // Light view space: the part of a receiver nearer the light than the caster's bounds cannot
  // be in its shadow (and behind the light nothing is): keep -z >= caster_front.
  std::vector<glm::vec4> view_planes = {{0.0f, 0.0f, -1.0f, -view.caster_front}};
  view_planes.insert(view_planes.end(), view.tile_planes.begin(), view.tile_planes.end());
  const glm::mat4 world_from_view = glm::inverse(view.view);
  // A flat caster (planar_caster; world, positive on the light's side) shadows nothing on the
  // light's side of its plane: receivers are clipped to the far side (light view space, a world
  // plane p is transpose(world_from_view) p there), and where the caster passes through one
  // that clip is the shadow's edge, exact to the pixel (a texture's edge there moves it by up
  // to a texel: issue 14, a plate through a cylinder seen close). Flag 0x80 per vertex below.
  const std::optional<glm::vec4> flat =
      caster_plane ? *caster_plane : planar_caster(scene.objects[caster], light.position);
  if (flat) view_planes.push_back(-(glm::transpose(world_from_view) * *flat));
  std::vector<glm::vec4> band_planes;  // view_planes and the receiver's depth band's plane
  // The light's inner beam (light_beam.h) in light view space: no shadow outside it.
  std::vector<std::vector<glm::vec4>> beam_regions;
  for (const std::vector<glm::vec4> &region : view.beam.regions) {
    beam_regions.emplace_back();
    for (const glm::vec4 &plane : region) {
      beam_regions.back().push_back(glm::transpose(world_from_view) * plane);
    }
  }
  const LightBeam &beam = view.beam;
  const FootprintSpace footprint = footprint_space(scene, frame, view);
  const SilhouetteRows silhouette_rows(view);
  std::vector<ClipVertex> polygon, scratch, footprint_polygon;
  std::vector<glm::vec4> footprint_planes;
  // The silhouette segments' boxes in the texture (light screen, texels; the whole plane for a
  // segment reaching behind the light), to pick those that can land on a polygon.
  std::vector<glm::vec4> segment_boxes;
  std::vector<SilhouetteSegment> segments = view.silhouette_segments;
  std::vector<glm::vec4> cut_planes;  // world: a light view plane p is transpose(view) p there
  for (const glm::vec4 &plane : view.edge_planes) cut_planes.push_back(glm::transpose(view.view) * plane);
  complete_cuts(scene.objects[caster], light.position, cut_planes, segments);
  mark_rims(view.rims, segments);
  for (const SilhouetteSegment &segment : segments) {
    glm::vec2 low(-INFINITY), high(INFINITY);
    const glm::vec4 ends[2] = {light_clip * glm::vec4(segment.a, 1.0f),
                               light_clip * glm::vec4(segment.b, 1.0f)};
    if (ends[0].w > 0.0f && ends[1].w > 0.0f) texel_box(view, ends, 2, low, high);
    segment_boxes.emplace_back(low, high);
  }
  SegmentGrid segment_grid(static_cast<float>(view.size), std::move(segment_boxes));
  CasterSurfacesFromLight own(scene.objects[caster]);
  CasterSurfacesFromLight &built = surfaces ? *surfaces : own;
  const CasterSurfaceFromLight &caster_surface = built.at(light_clip);
  std::vector<std::size_t> candidates;
  std::vector<DrawnTriangle> drawn;  // step 4's triangles of the receiver triangle in hand
  std::vector<DrawnPiece> drawn_pieces;
  EdgeErrorEstimate receiver_edge_error;  // of the receiver in hand
  // A receiver whose surface masks the texture (a depth band): the caster's cut through it is an
  // edge of the shadow there too (surface_cuts.h), with the contact strips step 1 kept.
  bool masked_band = false;
  std::optional<SurfaceCuts::Faces> own_cut_faces;  // without the view's (LightView::cut_faces)
  std::optional<SurfaceCuts> cuts;
  // The texels' footprint on the part of a receiver polygon that can be shadowed (world
  // corners, and their light clip coordinates), and the error along the shadow's edges there.
  auto measure_footprint = [&](std::size_t receiver, const glm::vec3 &normal,
                               const glm::vec3 *const *corners, const glm::vec4 *corners_clip,
                               std::size_t count) {
    footprint_planes = footprint.planes;
    if (!edge_rectangle(view, silhouette_rows, corners_clip, count, light_clip, footprint_planes)) {
      return;
    }
    footprint_polygon.clear();
    for (std::size_t k = 0; k < count; ++k) {
      footprint_polygon.push_back({glm::vec4(*corners[k], 1.0f), *corners[k], {}});
    }
    FootprintSample sample =
        texel_footprint(footprint, normal, footprint_planes, footprint_polygon, scratch);
    if (sample.screen_area <= 0.0f) return;
    sample.receiver = receiver;
    coords.footprints.push_back(sample);
    // The shadow's edges, thrown from the light, land on the polygon only within its box in
    // the texture (light screen texels; a texel more for the filter's reach).
    glm::vec2 low(INFINITY), high(-INFINITY);
    for (const ClipVertex &v : footprint_polygon) {
      const glm::vec4 clip = light_clip * glm::vec4(v.world, 1.0f);
      glm::vec2 box_low, box_high;
      texel_box(view, &clip, 1, box_low, box_high);
      low = glm::min(low, box_low - 1.0f), high = glm::max(high, box_high + 1.0f);
    }
    segment_grid.overlapping(low, high, candidates);
    if (masked_band && !cuts) {
      // An open caster (one with a rim) is drawn from both sides: each face cuts as the light
      // sees it.
      std::optional<SurfaceCuts::Faces> &faces = view.cut_faces ? *view.cut_faces : own_cut_faces;
      if (!faces) faces.emplace(scene.objects[caster], light.position, !view.rims.empty());
      cuts.emplace(*faces, view.contact_strips);
    }
    add_shadow_edge_error(footprint, light.position, scene.camera.position, normal,
                          footprint_polygon, segments, candidates,
                          options.bilinear && !options.chroma_key, receiver_edge_error,
                          masked_band ? &*cuts : nullptr);
  };

  std::vector<glm::vec4> lc;    // the receiver in hand's vertices, light clip, and their
  std::vector<unsigned> flags;  // Listing 2 flags (below)
  for (std::size_t r = 0; r < frame.objects.size(); ++r) {
    const ProjectedObject &receiver = frame.objects[r];
    if (r == caster || !receiver.object->receives_shadow) continue;
    if (receivers && !(*receivers)[r]) continue;
    receiver_edge_error = {};
    // The depth band (light view space, -z against caster_back; the two bands' planes are each
    // other negated, so both cut a receiver at the same points) and its flag 0x40 per vertex.
    const signed char band = depth_bands ? (*depth_bands)[r] : 0;
    masked_band = band != 0;
    // -1, -2, -3 (and -4, never cut): keep -z <= back; +1: keep -z >= back
    const float side = band < 0 ? -1.0f : static_cast<float>(band);
    band_planes = view_planes;
    band_planes.push_back(glm::vec4(0.0f, 0.0f, -side, -side * caster_back));
    // The receiver's own surface (light clip), taken at its first triangle across the band's
    // plane (built once per receiver and matrix, shared by both bands' textures): one that no
    // part of the receiver hides from the light is its surface the mask drew, where the masked
    // texture is exact, so it takes that texture whole and is not cut.
    const CasterSurfaceFromLight *own_surface = nullptr;
    const std::size_t n = receiver.world.size();
    lc.resize(n);  // light clip
    flags.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      lc[i] = light_clip * glm::vec4(receiver.world[i], 1.0f);
      const glm::vec4 &p = lc[i];
      flags[i] = (p.x < -p.w) | (p.x > p.w) << 1 | (p.y < -p.w) << 2 | (p.y > p.w) << 3 |
                 (p.w < view.caster_front) << 4;
      // Bit 0x20: no lit piece of the beam surely holds it; else its piece from bit 8 up.
      const int region = beam_regions.empty() ? 0 : beam.region_holding(receiver.world[i]);
      flags[i] |= region < 0 ? 0x20u : static_cast<unsigned>(region) << 8;
      if ((band < 0 && p.w > caster_back) || (band > 0 && p.w < caster_back)) flags[i] |= 0x40;
      if (flat && glm::dot(*flat, glm::vec4(receiver.world[i], 1.0f)) > 0.0f) flags[i] |= 0x80;
    }
    const std::vector<glm::uvec3> &triangles = receiver.object->mesh.triangles;
    for (const glm::uvec3 &t : triangles) {
      const auto number = static_cast<std::size_t>(&t - triangles.data());  // in the mesh
      const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
      // Listing 2: skip triangles facing away from the light and those wholly outside its view
      // (or on the light's side of a flat caster's plane).
      const glm::vec3 face = glm::cross(b - a, c - a);  // world, towards the lit side
      if (glm::dot(face, light.position - a) <= 0.0f) continue;
      if ((flags[t.x] & flags[t.y] & flags[t.z] & 0xDF) != 0) continue;
      unsigned any_outside = flags[t.x] | flags[t.y] | flags[t.z];
      // Nearer the light than the band's plane, the receiver's triangles that its own surface
      // hides from the light (in part) take the texture masked by its farthest light-facing
      // surface (band -2), the others the one masked by its nearest (-1): a caster part that
      // the nearer surface hides still shadows the farther one (a cylinder sunk through a
      // dune, the dune's far slope; the truth lets light through a receiver that casts nothing,
      // and one that casts shadows its far parts itself, uncounted). That texture is exact for
      // the farthest layer only: with `hidden_classes` (hidden_layers.h), the hidden triangles
      // that no other hidden one hides take band -3's instead. Beyond the plane (+1) the
      // whole caster's texture, except where the receiver hides nothing: the masked one, whole.
      if (band == -4) {
        // Band -4 (hidden_layers.h, hidden_marked): band -1's marked triangles that the
        // receiver's own surface hides in part, whole, with the texture masked by their surface.
        if (!hidden_classes || number >= hidden_classes->size() || (*hidden_classes)[number] == 0) {
          continue;
        }
        any_outside &= ~0x40u;
      } else if (band != 0 && (band < 0 || (any_outside & 0x40) != 0)) {
        if (!own_surface) {
          own_surface = &built.receiver_at(*receiver.object, light_clip,
                                           std::max(view.caster_front, 1e-6f));
        }
        const glm::vec4 corners[3] = {lc[t.x], lc[t.y], lc[t.z]};
        // A triangle in front of a caster part with a farther layer behind (over_buried) would
        // take that part's shadow from band -2's texture: band -1's, as if nothing hid it.
        const bool hidden = own_surface->may_shadow_triangle(*receiver.object, number, corners) &&
                            !(band < 0 && over_buried && (*over_buried)[number] != 0);
        if (band == -1 && hidden) {
          coords.hidden_left = coords.hidden_left || (flags[t.x] & flags[t.y] & flags[t.z] & 0x40) == 0;
          continue;
        }
        if (band <= -2 && !hidden) continue;
        // The hidden ones split by their layer (hidden_layers.h): the middle layer's (kHiddenOnce)
        // take band -3's texture, masked by the hidden triangles' nearest surface.
        const std::uint8_t layer = band == -3 ? kHiddenOnce : kHiddenTwice;
        if (hidden_classes && (*hidden_classes)[number] != layer) continue;
        if (!hidden) {
          if (band > 0) continue;  // the masked texture's, whole
          any_outside &= ~0x40u;
        }
      }
      const std::vector<glm::vec4> &planes = (any_outside & 0x40) != 0 ? band_planes : view_planes;
      const bool in_front = (any_outside & 0xD0) != 0;  // of the caster's front, or its plane
      // Corners in different pieces (a gobo's panes) leave a bar between them.
      const bool beyond_beam = (any_outside & 0x20) != 0 ||
                               ((flags[t.x] ^ flags[t.y]) | (flags[t.x] ^ flags[t.z])) >> 8 != 0;
      const bool needs_clip =
          in_front || beyond_beam || (!view.tile_planes.empty() && (any_outside & 0xF) != 0);
      if (!needs_clip) {
        const glm::vec4 corners[3] = {lc[t.x], lc[t.y], lc[t.z]};
        if (!sees_caster(view, corners, 3)) continue;
      }
      // Wholly nearer the light than the caster's surface behind it: never in its shadow. An
      // exact triangle stays in the list, as Listing 2 flags it, but step 5 does not draw it.
      const glm::vec4 light_corners[3] = {lc[t.x], lc[t.y], lc[t.z]};
      const bool may_shadow = caster_surface.may_shadow_triangle(*receiver.object, number, light_corners);
      const bool exact = !needs_clip &&
                         (receiver.outside[t.x] | receiver.outside[t.y] | receiver.outside[t.z]) == 0;
      if (!may_shadow && !exact) continue;
      if (exact) {
        ShadowTriangle triangle;
        const unsigned index[3] = {t.x, t.y, t.z};
        for (int k = 0; k < 3; ++k) {
          triangle.v[k] = receiver.screen[index[k]];
          set_texture_fields(triangle.v[k], view, light_clip, light, receiver.world[index[k]],
                             options);
        }
        const glm::vec4 corners[3] = {lc[t.x], lc[t.y], lc[t.z]};
        triangle.reaches_caster = may_shadow && reaches_covered_cell(view, corners, 3);
        if (triangle.reaches_caster) {
          const glm::vec3 *const world[3] = {&a, &b, &c};
          measure_footprint(r, glm::normalize(face), world, corners, 3);
        }
        coords.triangles.push_back(triangle);
        continue;
      }
      polygon.clear();
      for (unsigned i : {t.x, t.y, t.z}) {
        polygon.push_back({view.view * glm::vec4(receiver.world[i], 1.0f), receiver.world[i], {}});
      }
      for (const glm::vec4 &plane : planes) {
        clip_polygon(polygon, plane, scratch);
        if (polygon.size() < 3) break;
      }
      if (polygon.size() < 3) continue;
      step4_triangles(frame, scene, receiver, t, drawn);
      const ReceiverPlane receiver_plane(frame, scene, view.view, a, face);
      // Beyond the beam's sure inside: one piece per lit region (light_beam.h).
      const std::size_t pieces = beyond_beam ? beam_regions.size() : 1;
      for (std::size_t piece = 0; piece < pieces; ++piece) {
        std::vector<ClipVertex> part = polygon;
        std::vector<glm::vec4> piece_planes = planes;  // light view space
        if (beyond_beam) {
          piece_planes.insert(piece_planes.end(), beam_regions[piece].begin(), beam_regions[piece].end());
          for (const glm::vec4 &plane : beam_regions[piece]) {
            if (part.size() < 3) break;
            clip_polygon(part, plane, scratch);
          }
        }
        if (part.size() < 3) continue;
        std::vector<glm::vec4> corners;
        for (const ClipVertex &v : part) corners.push_back(view.projection * v.clip);
        if (!sees_caster(view, corners.data(), corners.size())) continue;
        std::vector<const glm::vec3 *> world;
        for (const ClipVertex &v : part) world.push_back(&v.world);
        measure_footprint(r, glm::normalize(face), world.data(), corners.data(), world.size());
        // Step 4's triangles clipped to the piece, with their depth (receiver_depth_planes.h).
        drawn_pieces.clear();
        cut_drawn(drawn, receiver_plane, piece_planes, drawn_pieces);
        for (const DrawnPiece &drawn_piece : drawn_pieces) {
          std::vector<GrVertex> screen(drawn_piece.size());  // value-initialised: all fields 0
          for (std::size_t i = 0; i < screen.size(); ++i) {
            screen[i].x = drawn_piece[i].screen.x, screen[i].y = drawn_piece[i].screen.y;
            screen[i].oow = drawn_piece[i].oow;
            set_texture_fields(screen[i], view, light_clip, light, drawn_piece[i].world, options);
          }
          coords.clipped.push_back(std::move(screen));
        }
      }
    }
    coords.edge_error.add(receiver_edge_error);
    if (receiver_edge_error.pixels[0] > coords.edge_error_receiver_pixels) {
      coords.edge_error_receiver = r;
      coords.edge_error_receiver_pixels = receiver_edge_error.pixels[0];
    }
  }
  return coords;
}

}  // namespace gs
