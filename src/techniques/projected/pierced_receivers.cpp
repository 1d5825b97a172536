// Which receivers a caster reaches through, from the light's side (world space): each
// receiver's plane from its largest triangle, its vertices checked against it, the caster's
// world vertices checked beyond it; a receiver that is not planar is left to pierced_surface
// (pierced_surfaces.cpp), but for a flat caster, whose own plane (found the same way) step 3
// clips the receivers to.
#include "techniques/projected/pierced_receivers.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace gs {
namespace {

// The plane (world space, unit normal, the light on its positive side) of `world` (an object's
// vertices, world space, and its `triangles`) if all of them lie in it; false otherwise, or if
// the light is in the plane.
bool plane_of(const std::vector<glm::vec3> &world, const std::vector<glm::uvec3> &triangles,
              const glm::vec3 &light, glm::vec4 &plane) {
  if (world.size() < 3) return false;
  glm::vec3 normal(0.0f);
  float largest = 0.0f;
  for (const glm::uvec3 &t : triangles) {
    const glm::vec3 n = glm::cross(world[t.y] - world[t.x], world[t.z] - world[t.x]);
    const float area = glm::length(n);
    if (area > largest) largest = area, normal = n / area;
  }
  if (!(largest > 0.0f)) return false;
  glm::vec3 low = world[0], high = world[0];
  for (const glm::vec3 &p : world) low = glm::min(low, p), high = glm::max(high, p);
  const float extent = glm::length(high - low);
  const float offset = -glm::dot(normal, world[0]);
  for (const glm::vec3 &p : world) {
    if (std::abs(glm::dot(normal, p) + offset) > 1e-5f * extent) return false;
  }
  const float light_side = glm::dot(normal, light) + offset;
  if (std::abs(light_side) <= 1e-5f * extent) return false;
  plane = light_side > 0.0f ? glm::vec4(normal, offset) : -glm::vec4(normal, offset);
  return true;
}

// The caster's vertices (caster_mesh, step 1's) in world space.
std::vector<glm::vec3> caster_world_positions(const SceneObject &object) {
  const Mesh &mesh = caster_mesh(object);
  std::vector<glm::vec3> world(mesh.positions.size());
  for (std::size_t i = 0; i < world.size(); ++i) {
    world[i] = glm::vec3(object.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
  }
  return world;
}

}  // namespace

std::optional<glm::vec4> planar_caster(const SceneObject &caster, const glm::vec3 &light_position) {
  glm::vec4 plane;
  if (!plane_of(caster_world_positions(caster), caster_mesh(caster).triangles, light_position, plane)) {
    return std::nullopt;
  }
  return plane;
}

std::vector<PiercedReceiver> pierced_receivers(const Scene &scene, const FrameGeometry &frame,
                                               std::size_t caster,
                                               const glm::vec3 &light_position) {
  std::vector<PiercedReceiver> pierced;
  const SceneObject &object = scene.objects[caster];
  const Mesh &mesh = caster_mesh(object);
  const std::vector<glm::vec3> caster_world = caster_world_positions(object);
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (const glm::vec3 &p : caster_world) low = glm::min(low, p), high = glm::max(high, p);
  if (caster_world.empty()) return pierced;
  // A flat caster shadows nothing on the light's side of its plane, and step 3 clips every
  // receiver to the far side (compute_receiver_coords): the clip is the cut through a receiver
  // that is not planar, exact to the pixel, where a mask by the receiver's surface holds it only
  // to a texel (issue 14: a plate through a cylinder, seen close).
  glm::vec4 caster_plane;
  const bool flat = plane_of(caster_world, mesh.triangles, light_position, caster_plane);
  const float tolerance = 1e-4f * glm::length(high - low);
  for (std::size_t r = 0; r < frame.objects.size(); ++r) {
    if (r == caster || !scene.objects[r].receives_shadow) continue;
    glm::vec4 plane;
    if (!plane_of(frame.objects[r].world, frame.objects[r].object->mesh.triangles, light_position,
                  plane)) {
      if (flat) continue;
      PiercedReceiver surface;
      surface.receiver = r;
      surface.planar = false;
      if (pierced_surface(frame.objects[r], caster_world, mesh.triangles, low, high, tolerance,
                          surface)) {
        pierced.push_back(std::move(surface));
      }
      continue;
    }
    const bool beyond = std::any_of(caster_world.begin(), caster_world.end(), [&](const glm::vec3 &p) {
      return glm::dot(plane, glm::vec4(p, 1.0f)) < -tolerance;
    });
    const bool before = std::any_of(caster_world.begin(), caster_world.end(), [&](const glm::vec3 &p) {
      return glm::dot(plane, glm::vec4(p, 1.0f)) > tolerance;
    });
    if (beyond) pierced.push_back({r, true, plane, before, {}, {}, {}});
  }
  return pierced;
}

float farthest_depth(const SceneObject &caster, const glm::mat4 &light_view) {
  float depth = 0.0f;
  for (const glm::vec3 &position : caster_mesh(caster).positions) {
    const glm::vec4 world = caster.model_to_world * glm::vec4(position, 1.0f);
    depth = std::max(depth, -(light_view * world).z);
  }
  return depth;
}

}  // namespace gs
