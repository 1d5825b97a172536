// The strips beside a caster's cut by a receiver's surface (contact_strips.h). World space in;
// the light's Glide screen (texels, y down) and light clip w (metres along the light's axis) out.
#include "techniques/projected/contact_strips.h"

#include "techniques/projected/contact_strip_rays.h"
#include "techniques/projected/pierced_receivers.h"
#include "techniques/projected/projected_shadow.h"
#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

namespace gs {

std::vector<ContactSegment> contact_segments(std::vector<ContactPoint> points) {
  const auto pair = [](const ContactPoint &x) {
    return std::make_pair(x.receiver_triangle, x.caster_triangle);
  };
  std::sort(points.begin(), points.end(),
            [&](const ContactPoint &x, const ContactPoint &y) { return pair(x) < pair(y); });
  std::vector<ContactSegment> contacts;
  for (std::size_t i = 0; i < points.size();) {
    std::size_t j = i + 1;
    while (j < points.size() && pair(points[j]) == pair(points[i])) ++j;
    ContactSegment contact{points[i].point, points[i].point, points[i].receiver_normal,
                           points[i].caster_normal};
    for (std::size_t k = i; k < j; ++k) {
      for (std::size_t l = k + 1; l < j; ++l) {
        const glm::vec3 &u = points[k].point, &v = points[l].point;
        if (glm::distance(u, v) > glm::distance(contact.a, contact.b)) contact.a = u, contact.b = v;
      }
    }
    if (contact.a != contact.b) contacts.push_back(contact);
    i = j;
  }
  return contacts;
}

namespace {

// Clips the segment a..b (the light's screen, texels) to the box low..high (Liang-Barsky): false
// when none of it lies in the box. A segment already inside keeps its ends exactly.
bool clip_to_box(glm::vec2 &a, glm::vec2 &b, const glm::vec2 &low, const glm::vec2 &high) {
  const glm::vec2 d = b - a;
  float enter = 0.0f, leave = 1.0f;
  for (int axis = 0; axis < 2; ++axis) {
    const float from_low = a[axis] - low[axis], to_high = high[axis] - a[axis];
    if (d[axis] == 0.0f) {
      if (from_low < 0.0f || to_high < 0.0f) return false;
      continue;
    }
    float t0 = -from_low / d[axis], t1 = to_high / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  if (!(enter < leave)) return false;
  const glm::vec2 start = a;
  if (leave < 1.0f) b = start + d * leave;
  if (enter > 0.0f) a = start + d * enter;
  return true;
}

}  // namespace

std::vector<std::array<GrVertex, 4>> contact_strips(const LightView &view,
                                                    const std::vector<ContactSegment> &contacts,
                                                    const SceneObject &caster, bool closed,
                                                    const ProjectedObject &receiver,
                                                    const glm::vec3 &camera,
                                                    const glm::mat4 &camera_clip) {
  std::vector<std::array<GrVertex, 4>> strips;
  if (contacts.empty()) return strips;
  const glm::mat4 light_clip = view.projection * view.view;
  const glm::mat4 clip_to_world = glm::inverse(light_clip);
  const float size = static_cast<float>(view.size);
  std::optional<ContactStripRays> rays;  // made for the first strip that needs its rays
  // The light clip w where the light's ray through a screen point (texels) meets a world plane;
  // false when it meets it behind the light or not at all.
  auto w_on_plane = [&](const glm::vec2 &screen, const glm::vec3 &normal, const glm::vec3 &point,
                        float &w) {
    const glm::vec2 ndc(screen.x / size * 2.0f - 1.0f, 1.0f - screen.y / size * 2.0f);
    const glm::vec4 far = clip_to_world * glm::vec4(ndc, 0.5f, 1.0f);
    const glm::vec3 direction = glm::vec3(far) / far.w - view.position;
    const float along = glm::dot(normal, direction);
    if (std::abs(along) < 1e-12f) return false;
    const float t = glm::dot(normal, point - view.position) / along;
    if (!(t > 0.0f)) return false;
    w = (light_clip * glm::vec4(view.position + direction * t, 1.0f)).w;
    return w > 0.0f;
  };
  const float k = kContactStripTexels;
  const float reach = kContactStripTexels;  // the filter's, around a texel a strip empties
  const float step = 0.5f;                  // between the rays, texels
  const float margin = k + reach;
  // The cuts step 1 draws, each as its ends in the light's screen (texels), and the box of the
  // rays around them all.
  struct Cut {
    const ContactSegment *contact;
    glm::vec2 a, b;
  };
  std::vector<Cut> cuts;
  glm::vec2 rays_low(INFINITY), rays_high(-INFINITY);
  for (const ContactSegment &c : contacts) {
    if (glm::dot(c.receiver_normal, view.position - c.a) <= 0.0f ||
        (closed && glm::dot(c.caster_normal, view.position - c.a) <= 0.0f)) {
      continue;  // not drawn in step 1 (the receiver's mask, the closed caster): no cut to hide
    }
    const glm::vec4 clip_a = light_clip * glm::vec4(c.a, 1.0f);
    const glm::vec4 clip_b = light_clip * glm::vec4(c.b, 1.0f);
    if (!(clip_a.w > 0.0f && clip_b.w > 0.0f)) continue;
    const GrVertex va = to_screen(clip_a, view.size, view.size);
    const GrVertex vb = to_screen(clip_b, view.size, view.size);
    glm::vec2 a(va.x, va.y), b(vb.x, vb.y);
    if (!(glm::length(b - a) > 0.0f)) continue;  // the segment along a light ray: no width to hide
    // Only the part of the cut whose strip or rays can reach a texel matters: a cut through a
    // receiver near the light can lie thousands of texels past the light's screen
    // (grazing-extra-lights_21107: 641,249 texels long on a 256-texel screen, 32 million rays,
    // the frame unfinished after minutes). The screen's image of the world segment is straight
    // (both ends before the light), so it is clipped there, to the screen grown by a ray's reach.
    if (!clip_to_box(a, b, glm::vec2(-(margin + step)), glm::vec2(size + margin + step))) continue;
    cuts.push_back({&c, a, b});
    // Every ray (the grid below) lies within margin + step of the cut along it and across it,
    // so less than twice that from a or b on each axis: a box that much wider holds them all.
    rays_low = glm::min(rays_low, glm::min(a, b) - glm::vec2(2.0f * (margin + step)));
    rays_high = glm::max(rays_high, glm::max(a, b) + glm::vec2(2.0f * (margin + step)));
  }
  for (const Cut &cut : cuts) {
    const ContactSegment &c = *cut.contact;
    const glm::vec2 a = cut.a, b = cut.b;
    const float screen_length = glm::length(b - a);
    // Both sides of the cut alike: the hidden side (the caster's plane in front of the
    // receiver) and the visible one (behind it, by less than a code near the line). Screen
    // points as (along the cut from a, across it), texels.
    const glm::vec2 along = (b - a) / screen_length;
    const glm::vec2 in(-along.y, along.x);
    auto at = [&](float s, float d) { return a + along * s + in * d; };
    // The strip in pieces about a texel long, each side of the cut apart. The rays on a grid
    // over the strip and a filter's reach around it find receiver points the camera may see in
    // the caster's shadow (contact_strip_rays.h): a side of a piece is kept when no such ray
    // lies within the filter's reach of it. A ray is cast only while a side it would drop is
    // still kept.
    const int pieces = std::max(1, static_cast<int>(std::ceil(screen_length + 2.0f * k)));
    const float piece = (screen_length + 2.0f * k) / static_cast<float>(pieces);
    std::vector<int> kept_sides(static_cast<std::size_t>(pieces), 3);  // bit 0: across < 0
    const int columns = static_cast<int>(std::ceil((screen_length + 2.0f * margin) / step)) + 1;
    const int rows = static_cast<int>(std::ceil(2.0f * margin / step)) + 1;
    const glm::vec2 ends[4] = {at(-margin, -margin), at(screen_length + margin, margin),
                               at(-margin, margin), at(screen_length + margin, -margin)};
    if (!rays) rays.emplace(view, caster, closed, receiver, camera, camera_clip, rays_low, rays_high);
    rays->select(glm::min(glm::min(ends[0], ends[1]), glm::min(ends[2], ends[3])),
                glm::max(glm::max(ends[0], ends[1]), glm::max(ends[2], ends[3])));
    for (int i = 0; i < columns; ++i) {
      const float s = -margin + step * static_cast<float>(i);
      // The pieces within reach of this column: s_low - reach <= s <= s_high + reach.
      // One more each way against rounding; the test below is exact.
      const int first = std::max(0, static_cast<int>(std::ceil((s - reach + k) / piece)) - 2);
      const int last = std::min(pieces - 1, static_cast<int>(std::floor((s + reach + k) / piece)) + 1);
      for (int j = 0; j < rows; ++j) {
        const float d = -margin + step * static_cast<float>(j);
        const int near_sides = (d <= reach ? 1 : 0) | (d >= -reach ? 2 : 0);
        int dropped = 0;  // the sides this ray would drop, of pieces first..last
        for (int p = first; p <= last; ++p) {
          const float s_low = -k + piece * static_cast<float>(p), s_high = s_low + piece;
          if (s >= s_low - reach && s <= s_high + reach) {
            dropped |= kept_sides[static_cast<std::size_t>(p)] & near_sides;
          }
        }
        if (dropped == 0) continue;
        const ContactStripRays::Seen seen = rays->seen_in_shadow(at(s, d));
        if (seen == ContactStripRays::Seen::kNone) continue;
        // A point seen inside the caster (the camera inside it) reads the other side's texels
        // within its reach as light all the same: the caster lies behind the receiver there. Its
        // own side's strip goes; the other's stays, which keeps step 1's coin toss along the cut
        // out of them. A point on the cut itself drops neither (the rays beside it decide).
        const int drop = seen == ContactStripRays::Seen::kOutside ? near_sides
                         : d < 0.0f                                ? near_sides & 1
                         : d > 0.0f                                ? near_sides & 2
                                                                   : 0;
        for (int p = first; p <= last; ++p) {
          const float s_low = -k + piece * static_cast<float>(p), s_high = s_low + piece;
          if (s >= s_low - reach && s <= s_high + reach) {
            kept_sides[static_cast<std::size_t>(p)] &= ~drop;
          }
        }
      }
    }
    auto sides = [&](int p) { return kept_sides[static_cast<std::size_t>(p)]; };
    for (int first = 0; first < pieces;) {
      const int kept = sides(first);
      int last = first;
      while (last + 1 < pieces && sides(last + 1) == kept) ++last;
      const float s_low = -k + piece * static_cast<float>(first);
      const float s_high = -k + piece * static_cast<float>(last + 1);
      first = last + 1;
      if (kept == 0) continue;
      const float d_low = kept & 1 ? -k : 0.0f, d_high = kept & 2 ? k : 0.0f;
      const glm::vec2 corners[4] = {at(s_low, d_low), at(s_high, d_low), at(s_high, d_high),
                                    at(s_low, d_high)};
      std::array<GrVertex, 4> strip;
      bool placed = true;
      for (int i = 0; i < 4 && placed; ++i) {
        float w_receiver = 0.0f, w_caster = 0.0f;
        placed = w_on_plane(corners[i], c.receiver_normal, c.a, w_receiver) &&
                 w_on_plane(corners[i], c.caster_normal, c.a, w_caster);
        // A few W-buffer codes nearer than both planes, and no nearer than depth_oow's unit
        // (1/W at most 1).
        const float w = std::max(std::min(w_receiver, w_caster) * (1.0f - kContactStripDepthShare),
                                 0.5f * std::max(view.caster_front, 1e-3f));
        std::memset(&strip[static_cast<std::size_t>(i)], 0, sizeof(GrVertex));
        strip[static_cast<std::size_t>(i)].x = corners[i].x;
        strip[static_cast<std::size_t>(i)].y = corners[i].y;
        strip[static_cast<std::size_t>(i)].oow = depth_oow(view, w);
      }
      if (placed) strips.push_back(strip);
    }
  }
  return strips;
}

}  // namespace gs
