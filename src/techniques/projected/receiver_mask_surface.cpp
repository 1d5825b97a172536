// Step 1's depth of a receiver's light-facing surface, which the caster is tested against
// (pierced_receivers.h, draw_mask_surface): the surface's triangles clipped to the light's view,
// fins along its outline from the light, and the contact strips beside the caster's cut. Light
// view and light clip space in, the light's size x size Glide screen (texels) out.
#include "techniques/projected/pierced_receivers.h"
#include "techniques/projected/receiver_outline.h"

#include "techniques/geometry/projection.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide.h>
#include <glideutl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gs {
namespace {

// A strip kFinTexels wide (the light's screen, texels) outside the edge p..q of a triangle whose
// third corner is r, and as far beyond both ends, at the edge's own depth (1/W of its ends): a
// texel centre that bilinear filtering reads for a point of the receiver (less than a texel away
// on each axis, so within sqrt 2, plus the shim's 1/16 snapping) lies in the triangle or in the
// strip. Wound as p, q, r are, so the caster's cull mode keeps it.
// A farthest-surface mask (`farthest`, depth test GREATER) keeps the greater W: its fin only
// carries the edge's W over a nearer layer or the clear, never hides a farther one, so it is
// drawn whatever lies beyond, and from kFinInwardTexels back over the edge, as the fin's corners
// snap (1/16 texel) apart from the triangle's and a sliver's texel centre could fall between.
// Else the far slope of a dune the light grazes (issue 14, sf1) read the crest beyond its
// outline, or nothing, as no caster there: alpha 0 over many pixels.
constexpr float kFinTexels = 1.5f;
constexpr float kFinInwardTexels = 0.125f;  // the light's screen, texels
void draw_fin(const GrVertex &p, const GrVertex &q, const GrVertex &r,
              const ReceiverOutline &outline,
              const glm::vec3 &p_world, const glm::vec3 &q_world, bool farthest) {
  const glm::vec2 a(p.x, p.y), b(q.x, q.y), third(r.x, r.y);
  const float length = glm::length(b - a);
  if (!(length > 0.0f)) return;
  const glm::vec2 along = (b - a) / length;
  glm::vec2 out(along.y, -along.x);
  if (glm::dot(out, third - a) > 0.0f) out = -out;
  const glm::vec2 inward = farthest ? -out * kFinInwardTexels : glm::vec2(0.0f);
  const glm::vec2 corners[4] = {a - along * kFinTexels + inward, b + along * kFinTexels + inward,
                                b + (along + out) * kFinTexels, a + (out - along) * kFinTexels};
  // Another layer of the receiver beyond the edge (a rope over the mat) takes the caster between
  // them as its shadow: no fin there (the texture holds one answer per texel), but in a
  // farthest-surface mask, where that layer's W wins where it is farther.
  if (!farthest && !outline.nothing_beyond(p_world, q_world, corners)) return;
  std::vector<GrVertex> quad(4, p);
  for (int k = 0; k < 4; ++k) {
    quad[static_cast<std::size_t>(k)].x = corners[k].x;
    quad[static_cast<std::size_t>(k)].y = corners[k].y;
    quad[static_cast<std::size_t>(k)].oow = k == 1 || k == 2 ? q.oow : p.oow;
  }
  const auto cross2 = [](const glm::vec2 &u, const glm::vec2 &v) { return u.x * v.y - u.y * v.x; };
  // Reversed when it turns the other way from p, q, r (r lies inward, the quad outward), so the
  // caster's cull mode keeps it.
  if ((cross2(b - a, third - a) > 0.0f) != (cross2(b - a, out) > 0.0f)) std::reverse(quad.begin(), quad.end());
  draw_fan(quad);
}

// Light clip w down to which a light-facing triangle is drawn: the caster's front (`front_w`),
// less as far as step 3's filter reaches across it. Step 3 shades the receiver from the front on,
// and a point just beyond it reads texel centres up to kFinTexels away on the light's screen,
// whose surface lies nearer the light: unmasked there, the texture held a caster part the
// receiver buries (a box sunk through a plate that a light grazes at 5 degrees, a texel 27 cm
// long on the plate: near-narrow-cones_22677, 0.143%). 1/w is affine over the triangle's plane
// on the light's screen, so the points within kFinTexels of the front line are those whose 1/w
// exceeds the front's by at most kFinTexels times its gradient (texels). `polygon` is the
// triangle clipped to w >= floor_w (> 0); the result is at least floor_w. An edge-on triangle
// covers no texel: the front as it is.
float reach_w(const std::vector<ClipVertex> &polygon, int size, float front_w, float floor_w) {
  glm::vec2 screen[8];  // the light's screen, texels; a triangle clipped by one plane has 4
  float inverse_w[8];
  const std::size_t n = std::min<std::size_t>(polygon.size(), 8);
  for (std::size_t i = 0; i < n; ++i) {
    const GrVertex v = to_screen(polygon[i].clip, size, size);
    screen[i] = {v.x, v.y}, inverse_w[i] = 1.0f / polygon[i].clip.w;
  }
  // The fan triangle of largest area gives the gradient best conditioned.
  float best_area = 0.0f;
  glm::vec2 gradient(0.0f);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const glm::vec2 e1 = screen[i] - screen[0], e2 = screen[i + 1] - screen[0];
    const float det = e1.x * e2.y - e1.y * e2.x;
    if (!(std::abs(det) > best_area)) continue;
    best_area = std::abs(det);
    const float d1 = inverse_w[i] - inverse_w[0], d2 = inverse_w[i + 1] - inverse_w[0];
    gradient = glm::vec2(d1 * e2.y - d2 * e1.y, e1.x * d2 - e2.x * d1) / det;
  }
  if (!(best_area > 1e-6f)) return front_w;
  const float reach_inverse_w = 1.0f / front_w + kFinTexels * glm::length(gradient);
  return std::max(floor_w, std::min(front_w, 1.0f / reach_inverse_w));
}

}  // namespace

float depth_oow(const LightView &view, float light_w) {
  return 0.5f * std::max(view.caster_front, 1e-3f) / light_w;
}

void draw_mask_surface(const LightView &view, const ProjectedObject &receiver, bool farthest,
                       const std::vector<std::uint8_t> *triangles) {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthMask(FXTRUE);
  grDepthBufferFunction(farthest ? GR_CMP_GREATER : GR_CMP_LESS);
  grColorMask(FXFALSE, FXFALSE);
  // Light clip space: beyond the caster's front (w >= caster_front) and as far before it as
  // step 3's filter reaches (reach_w), and the view's square a little wider (so the edge of the
  // texture is covered too). Step 3 never shades the part of a receiver nearer the light than the
  // caster's front (receiver_coords.cpp), so that part needs no protecting from the caster
  // behind it beyond the filter's reach; left in, it would hide a caster part lying between it
  // and a farther part of the same receiver (a post behind a ridge of its floor) from that
  // farther part, which the caster does shadow.
  const std::vector<glm::vec4> planes = {
      {0.0f, 0.0f, 0.0f, 1.0f}, {-1.0f, 0.0f, 0.0f, 1.01f}, {1.0f, 0.0f, 0.0f, 1.01f},
      {0.0f, -1.0f, 0.0f, 1.01f}, {0.0f, 1.0f, 0.0f, 1.01f}};
  const float front_w = std::max(view.caster_front, 1e-3f * std::max(view.caster_front, 1e-3f));
  // Light clip w: no triangle is drawn nearer than this (reach_w), which keeps its depth code
  // (depth_oow) at most 1.
  const float floor_w = 0.5f * front_w;
  const glm::mat4 light_clip = view.projection * view.view;
  std::vector<glm::vec4> clip(receiver.world.size());
  std::vector<unsigned> outside(receiver.world.size());
  for (std::size_t i = 0; i < clip.size(); ++i) {
    const glm::vec4 &p = clip[i] = light_clip * glm::vec4(receiver.world[i], 1.0f);
    outside[i] = (p.x < -p.w) | (p.x > p.w) << 1 | (p.y < -p.w) << 2 | (p.y > p.w) << 3 |
                 (p.w < front_w) << 4 | (p.w < floor_w) << 5;
  }
  // Light clip w >= cut (or <= cut, keep_nearer): (0, 0, 0, +-1) shifted by the constant. The
  // same shift on both sides of one cut gives the cut's points bit for bit (clip_polygon).
  const auto clip_at = [&](std::vector<ClipVertex> &polygon_in, float cut, bool keep_nearer,
                           std::vector<ClipVertex> &spare) {
    for (ClipVertex &v : polygon_in) v.clip.w -= cut;
    clip_polygon(polygon_in, keep_nearer ? -planes[0] : planes[0], spare);
    for (ClipVertex &v : polygon_in) v.clip.w += cut;
  };
  // A light-facing triangle is drawn in two parts: beyond the caster's front, cut there as its
  // neighbours are, and the band before the front down to its own reach_w. Cut at each
  // triangle's reach as one piece, neighbours sharing an edge ended it at different points,
  // whose snapped edges left a crack beyond the front that the caster showed through (a
  // panel's end face and broad face, fins20_panel_end_face_zoomed_light4, 1 pixel 92 px from
  // any true edge); in the band a crack costs no more than the band's absence did.
  std::vector<ClipVertex> beyond, before, scratch;
  std::vector<GrVertex> fan, band_fan;
  const ReceiverOutline outline = outline_of(view, receiver, clip);
  for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
    if ((outside[t.x] & outside[t.y] & outside[t.z] & ~0x10u) != 0) continue;
    const auto number = static_cast<std::size_t>(&t - receiver.object->mesh.triangles.data());
    if (triangles && (*triangles)[number] == 0) continue;  // not in a SurfaceMask::triangles
    const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
    if (glm::dot(glm::cross(b - a, c - a), view.position - a) <= 0.0f) continue;  // faces away
    beyond.clear();
    for (unsigned i : {t.x, t.y, t.z}) beyond.push_back({clip[i], receiver.world[i], {}});
    before.clear();
    float nearest_w = front_w;  // light clip w: this triangle's drawn part from here on
    if ((outside[t.x] | outside[t.y] | outside[t.z]) & 0x10) {
      before = beyond;
      clip_at(before, floor_w, false, scratch);  // from floor_w on, for reach_w's gradient
      if (before.size() < 3) continue;
      nearest_w = reach_w(before, view.size, front_w, floor_w);
      before = beyond;  // the band: cut from the whole triangle at the front, as `beyond` is
      clip_at(before, front_w, true, scratch);
      if (nearest_w < front_w) {
        clip_at(before, nearest_w, false, scratch);
      } else {
        before.clear();
      }
      clip_at(beyond, front_w, false, scratch);
    }
    if ((outside[t.x] | outside[t.y] | outside[t.z]) & 0x0F) {
      for (std::size_t k = 1; k < planes.size(); ++k) {
        if (beyond.size() >= 3) clip_polygon(beyond, planes[k], scratch);
        if (before.size() >= 3) clip_polygon(before, planes[k], scratch);
      }
    }
    if (beyond.size() < 3) beyond.clear();
    if (before.size() < 3) before.clear();
    if (beyond.empty() && before.empty()) continue;
    glm::vec2 low(INFINITY), high(-INFINITY);  // the light's screen (texels)
    const auto to_fan = [&](const std::vector<ClipVertex> &polygon, std::vector<GrVertex> &out) {
      out.clear();
      for (const ClipVertex &v : polygon) {
        GrVertex screen = to_screen(v.clip, view.size, view.size);
        screen.oow = depth_oow(view, v.clip.w);
        out.push_back(screen);
        low = glm::min(low, glm::vec2(screen.x, screen.y)), high = glm::max(high, glm::vec2(screen.x, screen.y));
      }
    };
    to_fan(beyond, fan);
    to_fan(before, band_fan);
    // Only where the caster draws does step 1 test depth, and a pixel both cover has its centre
    // within 1/16 texel (the shim's snapping) of both boxes: a surface triangle farther than a
    // texel from every covered cell writes no depth the caster is tested against (nor its fins
    // farther than that and their width).
    if (!view.covered_near(low, high, 1.0f + kFinTexels)) continue;
    if (view.covered_near(low, high, 1.0f)) {
      if (!fan.empty()) draw_fan(fan);
      if (!band_fan.empty()) draw_fan(band_fan);
    }
    // Along the receiver's outline from the light, the texture beyond it holds the caster behind
    // the receiver, which the receiver's own points next to the outline would read (the filter's
    // reach): its fins keep the caster there out of the texture, as the receiver's surface does
    // inside it (a box hovering over a ring's mat, issue 14). For a triangle reaching out of the
    // view's square, from its three corners unclipped (light screen, texels; the shim clips the
    // fin to the screen) when all lie beyond the caster's front (light clip w, so 1/W is
    // positive and finite) and within ReceiverOutline::kNear texels (where nothing_beyond's
    // separating axes keep their precision): a long side of a cylinder grazed by the light and leaving the
    // view had no fin, and the mat beyond its outline shadowed its lit edge
    // (sunk-camera-behind_18439, 0.156%). A triangle reaching nearer the light than the
    // caster's front has its outline edges clipped there (light clip w >= nearest_w), with the
    // drawn polygon's centre as the inward side: a panel's thin end face, 1.8 m to 8.4 m from
    // the light (light clip w) with the caster's front at 5.5 m, had no fin, and the caster
    // behind its outline shadowed it (near-extra-lights_20615, 0.131%).
    const auto far_off = [](const GrVertex &v) {
      return !(std::abs(v.x) < ReceiverOutline::kNear && std::abs(v.y) < ReceiverOutline::kNear);
    };
    const glm::vec3 *corner[3] = {&a, &b, &c};
    const unsigned index[3] = {t.x, t.y, t.z};
    if ((outside[t.x] | outside[t.y] | outside[t.z]) & 0x10) {
      // The light's screen, texels: inside the triangle's drawn part (its two pieces' corners'
      // mean).
      GrVertex inside = fan.empty() ? band_fan[0] : fan[0];
      inside.x = inside.y = 0.0f;
      for (const std::vector<GrVertex> *piece : {&fan, &band_fan}) {
        for (const GrVertex &v : *piece) inside.x += v.x, inside.y += v.y;
      }
      const auto corners = static_cast<float>(fan.size() + band_fan.size());
      inside.x /= corners, inside.y /= corners;
      for (int k = 0; k < 3; ++k) {
        if (!outline.contains(index[k], index[(k + 1) % 3])) continue;
        glm::vec4 ends[2] = {clip[index[k]], clip[index[(k + 1) % 3]]};  // light clip
        if (ends[0].w < nearest_w && ends[1].w < nearest_w) continue;
        for (int e = 0; e < 2; ++e) {
          glm::vec4 &end = ends[e];
          const glm::vec4 &other = ends[1 - e];
          if (end.w < nearest_w) end += (other - end) * ((nearest_w - end.w) / (other.w - end.w));
        }
        GrVertex fin_ends[2];
        for (int e = 0; e < 2; ++e) {
          fin_ends[e] = to_screen(ends[e], view.size, view.size);
          fin_ends[e].oow = depth_oow(view, ends[e].w);
        }
        if (far_off(fin_ends[0]) || far_off(fin_ends[1])) continue;
        draw_fin(fin_ends[0], fin_ends[1], inside, outline, *corner[k], *corner[(k + 1) % 3], farthest);
      }
      continue;
    }
    if ((outside[t.x] | outside[t.y] | outside[t.z]) != 0) {
      fan.clear();
      for (unsigned i : {t.x, t.y, t.z}) {
        GrVertex screen = to_screen(clip[i], view.size, view.size);
        screen.oow = depth_oow(view, clip[i].w);
        fan.push_back(screen);
      }
      if (std::any_of(fan.begin(), fan.end(), far_off)) continue;
    }
    for (int k = 0; k < 3; ++k) {
      if (outline.contains(index[k], index[(k + 1) % 3])) {
        draw_fin(fan[static_cast<std::size_t>(k)], fan[static_cast<std::size_t>((k + 1) % 3)],
                 fan[static_cast<std::size_t>((k + 2) % 3)], outline, *corner[k], *corner[(k + 1) % 3],
                 farthest);
      }
    }
  }
  // Beside the caster's cut by this surface, on its hidden side, the caster is kept out as far
  // as filtering reaches (contact_strips.h); drawn whatever their winding (step 1 sets its
  // caster's cull mode again after this).
  if (!view.contact_strips.empty()) grCullMode(GR_CULL_DISABLE);
  for (const std::array<GrVertex, 4> &strip : view.contact_strips) {
    glm::vec2 low(INFINITY), high(-INFINITY);
    for (const GrVertex &v : strip) low = glm::min(low, glm::vec2(v.x, v.y)), high = glm::max(high, glm::vec2(v.x, v.y));
    if (view.covered_near(low, high, 1.0f)) draw_fan(std::vector<GrVertex>(strip.begin(), strip.end()));
  }
  grColorMask(FXTRUE, FXFALSE);
  grDepthMask(FXFALSE);
  grDepthBufferFunction(GR_CMP_LESS);  // the caster, nearer than the surface kept
}

}  // namespace gs
