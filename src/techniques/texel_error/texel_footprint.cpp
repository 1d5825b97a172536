// The texture-to-screen stretch of a projected shadow texture on a receiver polygon: both the
// light's and the camera's projections differentiated on the polygon's plane (world space), in
// texels and pixels per metre, and pixels per texel across the texel's stretch; and a whole
// shadow's footprint from its polygons'; the refusal of a shadow whose texels are too coarse.
#include "techniques/texel_error/texel_footprint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gs {
namespace {

// Pixels per texel at world point p on a plane with tangents t1, t2 (world space), across the
// direction the texel is most stretched in: the mapping's smallest singular value. Where the
// light grazes a surface its texels stretch along the light's direction, but so do the shadow
// edges there (an edge lies along L (N.E) - E (N.L) for a caster edge E, normal N and light
// direction L: along L as N.L goes to 0), and a texel moves an edge only across itself. The
// largest singular value called the fight's frames at 128 texels 47 to 93 px with 0.01 to
// 0.05% interior error (docs/hard_cases_results.md).
float stretch_at(const FootprintSpace &space, const glm::vec3 &p, const glm::vec3 &t1,
                 const glm::vec3 &t2) {
  // Texels and pixels per metre along the plane's tangents.
  const glm::mat2 texels = tangent_jacobian(space.light_clip, p, glm::vec2(space.texels), t1, t2);
  const glm::mat2 pixels = tangent_jacobian(space.camera_clip, p, space.pixels, t1, t2);
  const float det = glm::determinant(texels);
  // A plane edge-on to the light: one texel spans the whole plane. Finite, so it compares.
  if (!(std::abs(det) > 1e-12f)) return 1e9f;
  const glm::mat2 a = pixels * glm::inverse(texels);  // pixels per texel
  // Singular values of a 2x2 matrix from its squared Frobenius norm and its determinant:
  // largest^2 = (f + sqrt(f^2 - 4 d^2)) / 2, and largest x smallest = |d|.
  const float frobenius = a[0][0] * a[0][0] + a[0][1] * a[0][1] + a[1][0] * a[1][0] +
                          a[1][1] * a[1][1];
  const float d = glm::determinant(a);
  const float largest =
      std::sqrt(0.5f * (frobenius + std::sqrt(std::max(frobenius * frobenius - 4.0f * d * d, 0.0f))));
  return largest > 0.0f ? std::min(std::abs(d) / largest, 1e9f) : 0.0f;
}

}  // namespace

void plane_tangents(const glm::vec3 &normal, glm::vec3 &t1, glm::vec3 &t2) {
  const glm::vec3 helper = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  t1 = glm::normalize(glm::cross(normal, helper));
  t2 = glm::cross(normal, t1);
}

glm::mat2 tangent_jacobian(const glm::mat4 &clip_from_world, const glm::vec3 &p,
                           const glm::vec2 &extent, const glm::vec3 &t1, const glm::vec3 &t2) {
  const glm::vec4 c = clip_from_world * glm::vec4(p, 1.0f);
  auto row = [&](int r) {  // GLM is column-major: m[column][row]
    return glm::vec3(clip_from_world[0][r], clip_from_world[1][r], clip_from_world[2][r]);
  };
  const glm::vec3 dx = (row(0) - (c.x / c.w) * row(3)) / c.w * (0.5f * extent.x);
  const glm::vec3 dy = (row(1) - (c.y / c.w) * row(3)) / c.w * (0.5f * extent.y);
  return glm::mat2(glm::dot(dx, t1), glm::dot(dy, t1), glm::dot(dx, t2), glm::dot(dy, t2));
}

glm::vec2 footprint_screen_pixels(const FootprintSpace &space, const glm::vec3 &world) {
  const glm::vec4 c = space.camera_clip * glm::vec4(world, 1.0f);
  return glm::vec2(c.x, c.y) / c.w * 0.5f * space.pixels;
}

float polygon_area(const std::vector<glm::vec2> &polygon) {
  float twice_area = 0.0f;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec2 &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
    twice_area += a.x * b.y - a.y * b.x;
  }
  return 0.5f * std::abs(twice_area);
}

FootprintSample texel_footprint(const FootprintSpace &space, const glm::vec3 &normal,
                                const std::vector<glm::vec4> &planes,
                                std::vector<ClipVertex> &world, std::vector<ClipVertex> &scratch) {
  FootprintSample sample;
  for (const glm::vec4 &plane : planes) {
    if (world.size() < 3) return sample;
    clip_polygon(world, plane, scratch);
  }
  if (world.size() < 3) return sample;
  glm::vec3 t1, t2;
  plane_tangents(normal, t1, t2);
  // Screen pixels of the corners (inside the camera's view, so w > 0), for the area: summed
  // as polygon_area sums them, edge by edge from the first corner, without keeping them.
  glm::vec2 first(0.0f), previous(0.0f);
  float twice_area = 0.0f;
  for (std::size_t i = 0; i < world.size(); ++i) {
    const glm::vec3 &corner = world[i].world;
    sample.pixels_per_texel = std::max(sample.pixels_per_texel, stretch_at(space, corner, t1, t2));
    const glm::vec2 screen = footprint_screen_pixels(space, corner);
    if (i == 0) first = screen;
    else twice_area += previous.x * screen.y - previous.y * screen.x;
    previous = screen;
  }
  twice_area += previous.x * first.y - previous.y * first.x;
  sample.screen_area = 0.5f * std::abs(twice_area);
  return sample;
}

FootprintSample shadow_footprint(std::vector<FootprintSample> samples, float ignored_pixels) {
  std::sort(samples.begin(), samples.end(), [](const FootprintSample &a, const FootprintSample &b) {
    return a.pixels_per_texel > b.pixels_per_texel;
  });
  float left_out = 0.0f;
  for (const FootprintSample &sample : samples) {
    left_out += sample.screen_area;
    if (left_out > ignored_pixels) return sample;
  }
  return {};
}

std::string texel_footprint_error(const Scene &scene, std::size_t light, std::size_t caster,
                                  std::size_t receiver, float footprint, float largest, int size,
                                  const std::string &accepted_words) {
  return texel_footprint_reason(scene, light, caster, receiver, footprint, largest, size,
                                accepted_words) +
         "; " + kCastsNoShadow;
}

std::string texel_footprint_reason(const Scene &scene, std::size_t light, std::size_t caster,
                                   std::size_t receiver, float footprint, float largest, int size,
                                   const std::string &accepted_words) {
  char pixels[64];
  std::snprintf(pixels, sizeof pixels, "%.1f screen pixels (the largest accepted is %.1f)",
                static_cast<double>(footprint), static_cast<double>(largest));
  return "light " + std::to_string(light) + " and '" + scene.objects[caster].name +
         "': a shadow texel spans " + pixels + " on '" + scene.objects[receiver].name +
         "', so the " + std::to_string(size) + "-texel shadow is too coarse for the screen (" +
         accepted_words + ")";
}

}  // namespace gs
