// The beam's pyramids (light_beam.h), built in the light's view space (the light at the origin
// looking down -z, as light_view() sets it up) and carried to world space.
#include "techniques/geometry/light_beam.h"

#include "scene/spotlight.h"
#include "techniques/geometry/projection.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace gs {
namespace {

// A plane through the light's origin with view-space normal n, as a world plane.
glm::vec4 to_world(const glm::mat4 &view, const glm::vec3 &position, const glm::vec3 &n) {
  const glm::vec3 normal = glm::transpose(glm::mat3(view)) * n;  // the view's rotation inverted
  return {normal, -glm::dot(normal, position)};
}

}  // namespace

LightBeam light_beam(const SpotLight &light) {
  LightBeam beam;
  const glm::mat4 view = light_view(light);
  beam.position = light.position;
  beam.axis = glm::normalize(light.target - light.position);
  const float t = std::tan(glm::radians(light.cone_degrees) * 0.5f);  // beam plane's half side
  const bool square = light.has_beam_map() && (light.beam == "square" || light.beam_image);
  if (square) {
    // |x| <= t (-z) and |y| <= t (-z): the beam plane's [-1, 1]^2.
    for (const glm::vec3 &n : {glm::vec3(-1, 0, -t), glm::vec3(1, 0, -t), glm::vec3(0, -1, -t),
                               glm::vec3(0, 1, -t)}) {
      beam.inner.push_back(to_world(view, light.position, n));
    }
    beam.outer = beam.inner;
    beam.regions = {beam.inner};
    return beam;
  }
  // Tangent planes at azimuths phi_k hold the cone (x cos + y sin <= t (-z)); planes through
  // consecutive corners of the inscribed polygon (at phi_k + pi / n, distance t cos(pi / n)) lie
  // inside it.
  const float half_step = glm::pi<float>() / static_cast<float>(kConeSides);
  for (int k = 0; k < kConeSides; ++k) {
    const float phi = 2.0f * half_step * static_cast<float>(k);
    beam.outer.push_back(
        to_world(view, light.position, {-std::cos(phi), -std::sin(phi), -t}));
    beam.inner.push_back(to_world(view, light.position,
                                  {-std::cos(phi + half_step), -std::sin(phi + half_step),
                                   -t * std::cos(half_step)}));
  }
  // The cone inscribed in the inner pyramid, a little narrower for float rounding.
  beam.inner_cosine = std::cos(std::atan(t * std::cos(half_step) * 0.999f));
  if (light.beam == "gobo") {
    // The bars: |x| < 0.05 t (-z) and |y| < 0.05 t (-z) (spotlight.cpp's gobo_beam); each pane
    // keeps x (or y) on one side, e.g. x + 0.05 t z >= 0.
    for (float sx : {-1.0f, 1.0f}) {
      for (float sy : {-1.0f, 1.0f}) {
        std::vector<glm::vec4> pane = beam.inner;
        pane.push_back(to_world(view, light.position, {sx, 0.0f, 0.05f * t}));
        pane.push_back(to_world(view, light.position, {0.0f, sy, 0.05f * t}));
        beam.regions.push_back(std::move(pane));
      }
    }
    beam.inner_cosine = -2.0f;  // a point in the disc may be in a bar: only the planes tell
  } else {
    beam.regions = {beam.inner};
  }
  return beam;
}

int LightBeam::region_holding(const glm::vec3 &world) const {
  if (inner_cosine >= -1.0f) {
    // The cone inscribed in `inner`, the only piece.
    const glm::vec3 to_point = world - position;
    const float distance = glm::length(to_point);
    return distance > 0.0f && glm::dot(axis, to_point) >= inner_cosine * distance ? 0 : -1;
  }
  for (std::size_t r = 0; r < regions.size(); ++r) {
    if (inside_planes(regions[r], world)) return static_cast<int>(r);
  }
  return -1;
}

bool LightBeam::surely_holds_triangle(const glm::vec3 &a, const glm::vec3 &b,
                                      const glm::vec3 &c) const {
  const int region = region_holding(a);
  return region >= 0 && region_holding(b) == region && region_holding(c) == region;
}

bool inside_planes(const std::vector<glm::vec4> &planes, const glm::vec3 &world) {
  for (const glm::vec4 &plane : planes) {
    if (glm::dot(plane, glm::vec4(world, 1.0f)) < 0.0f) return false;
  }
  return true;
}

std::vector<glm::vec3> clip_to_beam(const std::vector<glm::vec3> &world,
                                    const std::vector<glm::uvec3> &triangles,
                                    const LightBeam &beam, float margin, bool &whole) {
  whole = true;
  if (world.empty()) return world;
  // Only the planes that can cut the mesh are tested. A plane the sphere around the vertices'
  // box (world) clears by far more than float rounding of dot(plane, (p, 1)) keeps every vertex
  // and every point between vertices (the clipped pieces' corners) inside: testing it, or
  // clipping by it, changes nothing. The fighters, inside the beam, test one plane, not 65.
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (const glm::vec3 &p : world) low = glm::min(low, p), high = glm::max(high, p);
  const glm::vec3 centre = (low + high) * 0.5f;
  const float radius = glm::length(high - low) * 0.5f;
  // Rounding of a plane test is a few ulps of |normal| (|p| + |light position|) + |margin|.
  const float rounding_scale =
      glm::length(centre) + radius + glm::length(beam.position) + std::fabs(margin) + 1.0f;
  std::vector<glm::vec4> planes;
  auto keep_if_it_can_cut = [&](const glm::vec4 &plane) {
    const float normal_length = glm::length(glm::vec3(plane));
    const float clearance = glm::dot(plane, glm::vec4(centre, 1.0f)) - normal_length * radius;
    if (!(clearance > 1e-4f * normal_length * rounding_scale)) planes.push_back(plane);
  };
  for (const glm::vec4 &plane : beam.outer) keep_if_it_can_cut(plane);
  keep_if_it_can_cut({beam.axis, -glm::dot(beam.axis, beam.position) - margin});
  std::vector<bool> inside(world.size());
  for (std::size_t i = 0; i < world.size(); ++i) {
    inside[i] = inside_planes(planes, world[i]);
    whole = whole && inside[i];
  }
  if (whole) return world;
  std::vector<glm::vec3> points;
  std::vector<ClipVertex> polygon, scratch;
  for (const glm::uvec3 &t : triangles) {
    if (t.x >= world.size() || t.y >= world.size() || t.z >= world.size()) continue;
    if (inside[t.x] && inside[t.y] && inside[t.z]) {
      points.insert(points.end(), {world[t.x], world[t.y], world[t.z]});
      continue;
    }
    polygon.clear();
    for (unsigned i : {t.x, t.y, t.z}) polygon.push_back({glm::vec4(world[i], 1.0f), world[i], {}});
    for (const glm::vec4 &plane : planes) {
      clip_polygon(polygon, plane, scratch);
      if (polygon.size() < 3) break;
    }
    if (polygon.size() < 3) continue;
    for (const ClipVertex &v : polygon) points.push_back(v.world);
  }
  return points;
}

}  // namespace gs
