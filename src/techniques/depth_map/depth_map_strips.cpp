// The interior error on a receiver seen as a thin strip (depth_map_strips.h): its pixel centres
// found from the camera (world, in double), the map's lookup replayed at each against a ray to
// the light, counted as the error measure counts.
#include "techniques/depth_map/depth_map_strips.h"

#include "techniques/depth_map/depth_map_replay.h"
#include "techniques/depth_map/triangle_bvh.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"
#include "techniques/texel_error/shadow_edge_error.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gs::depth_map {
namespace strips {

// A receiver whose pixels make a strip thinner than this (pixels) across its length leaves no
// room beside an edge along it for the measure's band (a boundary pixel and one more).
inline constexpr float kThinStripPx = 3.0f;

// One pixel centre of a strip: where the camera's ray meets it (world), its triangle's corners
// (world), and whether that triangle faces the light.
struct StripPixel {
  int x = 0, y = 0;
  dvec3 point{0.0};
  glm::vec3 corner[3];
  bool lit_side = false;
};

}  // namespace strips

std::vector<ContactError> strip_errors(const Scene &scene,
                                        const std::vector<WorldMesh> &meshes,
                                        const LightFrustum &frustum, const SpotLight &light,
                                        int side, const TechniqueOptions &options) {
  std::vector<ContactError> result(scene.objects.size());
  const FootprintSpace space = camera_screen(scene);
  const glm::dmat4 camera_clip(space.camera_clip), clip_to_world = glm::inverse(camera_clip);
  const dvec3 camera(scene.camera.position), light_position(light.position);
  const LightBeam beam = light_beam(light);
  const glm::mat4 to_map = texture_from_clip() * frustum.projection * frustum.view;
  const int width = scene.width, height = scene.height;
  std::vector<RayBody> bodies;  // made when a strip is found
  for (const WorldMesh &receiver : meshes) {
    if (!receiver.object->receives_shadow) continue;
    // Its triangles facing the camera, on screen (corners before the camera only).
    float area = 0.0f;
    glm::vec2 low(INFINITY), high(-INFINITY);  // pixels, x right, rows from the top
    std::vector<std::size_t> facing;           // their indices
    std::vector<glm::vec2> screen(3);
    for (std::size_t k = 0; k < receiver.object->mesh.triangles.size(); ++k) {
      const glm::uvec3 &t = receiver.object->mesh.triangles[k];
      const glm::vec3 &a = receiver.position[t.x], &b = receiver.position[t.y], &c = receiver.position[t.z];
      if (!(glm::dot(glm::cross(b - a, c - a), scene.camera.position - a) > 0.0f)) continue;
      bool before = true;
      for (int m = 0; m < 3; ++m) {
        const glm::vec3 &p = receiver.position[t[m]];
        before = before && (space.camera_clip * glm::vec4(p, 1.0f)).w > 0.0f;
        const glm::vec2 f = footprint_screen_pixels(space, p);
        screen[m] = glm::vec2(f.x + 0.5f * space.pixels.x, 0.5f * space.pixels.y - f.y);
      }
      if (!before) continue;
      // Only what the screen shows counts towards the strip's size.
      std::vector<glm::vec2> shown = screen;
      for (int axis = 0; axis < 2; ++axis) {
        for (const float sign : {1.0f, -1.0f}) {  // keep sign * (p[axis] - edge) >= 0
          const float edge = sign > 0.0f ? 0.0f : space.pixels[axis];
          std::vector<glm::vec2> kept;
          for (std::size_t i = 0; i < shown.size(); ++i) {
            const glm::vec2 &p = shown[i], &q = shown[(i + 1) % shown.size()];
            const float dp = sign * (p[axis] - edge), dq = sign * (q[axis] - edge);
            if (dp >= 0.0f) kept.push_back(p);
            if ((dp >= 0.0f) != (dq >= 0.0f)) kept.push_back(p + (q - p) * (dp / (dp - dq)));
          }
          shown.swap(kept);
        }
      }
      if (shown.size() < 3) continue;
      facing.push_back(k);
      area += std::abs(polygon_area(shown));
      for (const glm::vec2 &p : shown) low = glm::min(low, p), high = glm::max(high, p);
    }
    if (!(area > 0.0f)) continue;
    const glm::vec2 extent = glm::max(high - low, glm::vec2(1.0f));
    if (!(std::min(area / extent.x, area / extent.y) < strips::kThinStripPx)) continue;
    if (bodies.empty()) bodies = ray_bodies(meshes);
    const std::size_t receiver_at = static_cast<std::size_t>(&receiver - meshes.data());
    // Its pixel centres the camera sees it at: each facing triangle's, found by the camera's ray
    // through the centre, kept where no face turned to the camera hides them.
    std::vector<int> at(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), -1);
    std::vector<strips::StripPixel> pixels;
    for (std::size_t k : facing) {
      const glm::uvec3 &t = receiver.object->mesh.triangles[k];
      const dvec3 a(receiver.position[t.x]), b(receiver.position[t.y]), c(receiver.position[t.z]);
      glm::vec2 box_low(INFINITY), box_high(-INFINITY);
      for (int m = 0; m < 3; ++m) {
        const glm::vec2 f = footprint_screen_pixels(space, receiver.position[t[m]]);
        const glm::vec2 p(f.x + 0.5f * space.pixels.x, 0.5f * space.pixels.y - f.y);
        box_low = glm::min(box_low, p), box_high = glm::max(box_high, p);
      }
      const int x0 = std::max(0, static_cast<int>(std::floor(box_low.x - 0.5f)));
      const int x1 = std::min(width - 1, static_cast<int>(std::ceil(box_high.x - 0.5f)));
      const int y0 = std::max(0, static_cast<int>(std::floor(box_low.y - 0.5f)));
      const int y1 = std::min(height - 1, static_cast<int>(std::ceil(box_high.y - 0.5f)));
      const glm::vec3 face = glm::cross(receiver.position[t.y] - receiver.position[t.x],
                                        receiver.position[t.z] - receiver.position[t.x]);
      const bool lit_side = glm::dot(face, light.position - receiver.position[t.x]) > 0.0f;
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const std::size_t index = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
          if (at[index] >= 0) continue;
          const glm::dvec2 ndc((x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0);
          const glm::dvec4 near_end = clip_to_world * glm::dvec4(ndc, -1.0, 1.0);
          const glm::dvec4 far_end = clip_to_world * glm::dvec4(ndc, 1.0, 1.0);
          const dvec3 from = dvec3(near_end) / near_end.w, to = dvec3(far_end) / far_end.w;
          double hit = 0.0;
          if (!ray_meets_triangle(from, to - from, a, b, c, hit) || !(hit > 0.0 && hit < 1.0)) continue;
          strips::StripPixel pixel;
          pixel.x = x, pixel.y = y;
          pixel.point = from + (to - from) * hit;
          if (!seen_past_near_plane(bodies, camera_clip, camera, pixel.point, true)) continue;
          for (int m = 0; m < 3; ++m) pixel.corner[m] = receiver.position[t[m]];
          pixel.lit_side = lit_side;
          at[index] = static_cast<int>(pixels.size());
          pixels.push_back(pixel);
        }
      }
    }
    if (pixels.empty()) continue;
    for (std::size_t caster_at = 0; caster_at < meshes.size(); ++caster_at) {
      const WorldMesh &caster = meshes[caster_at];
      if (!caster.object->casts_shadow || caster_at == receiver_at) continue;
      // The truth per pixel from this caster: 1 shadow, 0 lit, -1 where it alone does not decide
      // (outside the beam or facing away, or another caster or the receiver shadows it too).
      std::vector<int> truth(pixels.size(), -1);
      bool any_shadow = false;
      for (std::size_t i = 0; i < pixels.size(); ++i) {
        const strips::StripPixel &pixel = pixels[i];
        if (!pixel.lit_side || !inside_planes(beam.inner, glm::vec3(pixel.point))) continue;
        bool alone = true;
        for (std::size_t m = 0; m < bodies.size() && alone; ++m) {
          if (m == caster_at || !(bodies[m].casts || m == receiver_at)) continue;
          alone = !blocks(bodies[m], light_position, pixel.point - light_position);
        }
        if (!alone) continue;
        truth[i] = blocks(bodies[caster_at], light_position, pixel.point - light_position) ? 1 : 0;
        any_shadow = any_shadow || truth[i] == 1;
      }
      if (!any_shadow) continue;
      // The measure's band: strip pixels within one (Chebyshev) of a pixel whose 4-neighbour on
      // the strip the truth calls otherwise.
      auto truth_at = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= width || y >= height) return -1;
        const int i = at[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
        return i < 0 ? -1 : truth[static_cast<std::size_t>(i)];
      };
      auto boundary = [&](int x, int y) {
        const int here = truth_at(x, y);
        if (here < 0) return false;
        for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
          const int there = truth_at(x + d.x, y + d.y);
          if (there >= 0 && there != here) return true;
        }
        return false;
      };
      const EdgeErrorEstimate estimate = estimate_by_size(side, [&](int map_side) {
        MapReplay replay = caster_replay(frustum, light, map_side, options, caster, receiver);
        long interior = 0;
        for (std::size_t i = 0; i < pixels.size(); ++i) {
          if (truth[i] < 0) continue;
          const strips::StripPixel &pixel = pixels[i];
          const double lowered = receiver_lowering(pixel.corner[0], pixel.corner[1], pixel.corner[2],
                                                   receiver.object->casts_shadow, to_map, map_side, options);
          glm::dvec2 texels;
          double depth;
          if (!replay.in_map(pixel.point, texels, depth)) continue;
          const int shadowed = replay.shadowed(texels, depth - lowered) ? 1 : 0;
          if (shadowed == truth[i]) continue;
          bool band = false;
          for (int dy = -1; dy <= 1 && !band; ++dy) {
            for (int dx = -1; dx <= 1 && !band; ++dx) band = boundary(pixel.x + dx, pixel.y + dy);
          }
          if (!band) ++interior;
        }
        return static_cast<double>(interior);
      });
      ContactError &error = result[static_cast<std::size_t>(caster.object - scene.objects.data())];
      if (estimate.pixels[0] > error.pixels.pixels[0]) {
        error.receiver = static_cast<std::size_t>(receiver.object - scene.objects.data());
      }
      error.pixels.add(estimate);
    }
  }
  return result;
}

}  // namespace gs::depth_map
