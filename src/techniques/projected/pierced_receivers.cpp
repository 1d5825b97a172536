// Which receivers a caster reaches through, from the light's side (world space): each
// receiver's plane from its largest triangle, its vertices checked against it, the caster's
// world vertices checked beyond it; a receiver that is not planar is left to pierced_surface
// (pierced_surfaces.cpp), but for a flat caster (planar_caster), whose own plane step 3 clips
// the receivers to.
#include "techniques/projected/pierced_receivers.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace gs {
namespace {

// The plane of a receiver (world space, unit normal, the light on its positive side) if all its
// vertices lie in it; false otherwise, or if the light is in the plane.
bool planar_receiver(const ProjectedObject &receiver, const glm::vec3 &light, glm::vec4 &plane) {
  const std::vector<glm::vec3> &world = receiver.world;
  if (world.size() < 3) return false;
  glm::vec3 normal(0.0f);
  float largest = 0.0f;
  for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
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

}  // namespace

std::optional<glm::vec4> planar_caster(const SceneObject &caster, const glm::vec3 &light_position) {
  // Cheap for a caster that is not flat (a fighter's 1,500 triangles, every frame): the plane
  // of its first triangle with an area, and the vertices put in the world and checked against
  // it one at a time, so such a caster leaves at its first vertex off the plane.
  const Mesh &mesh = caster_mesh(caster);
  if (mesh.positions.size() < 3) return std::nullopt;
  auto world = [&](const glm::vec3 &model) {
    return glm::vec3(caster.model_to_world * glm::vec4(model, 1.0f));
  };
  // The caster's extent (world): the diagonal of the box around its model box's corners.
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (const glm::vec3 &p : mesh.positions) low = glm::min(low, p), high = glm::max(high, p);
  glm::vec3 world_low(INFINITY), world_high(-INFINITY);
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner =
        world({k & 1 ? high.x : low.x, k & 2 ? high.y : low.y, k & 4 ? high.z : low.z});
    world_low = glm::min(world_low, corner), world_high = glm::max(world_high, corner);
  }
  const float tolerance = 1e-5f * glm::length(world_high - world_low);
  glm::vec3 normal(0.0f), point(0.0f);  // world, unit
  for (const glm::uvec3 &t : mesh.triangles) {
    const glm::vec3 a = world(mesh.positions[t.x]);
    const glm::vec3 n = glm::cross(world(mesh.positions[t.y]) - a, world(mesh.positions[t.z]) - a);
    const float area = glm::length(n);
    if (area > 0.0f) {
      normal = n / area, point = a;
      break;
    }
  }
  if (normal == glm::vec3(0.0f)) return std::nullopt;
  const float offset = -glm::dot(normal, point);
  for (const glm::vec3 &p : mesh.positions) {
    if (!(std::abs(glm::dot(normal, world(p)) + offset) <= tolerance)) return std::nullopt;
  }
  const float light_side = glm::dot(normal, light_position) + offset;
  if (!(std::abs(light_side) > tolerance)) return std::nullopt;
  return light_side > 0.0f ? glm::vec4(normal, offset) : -glm::vec4(normal, offset);
}

std::vector<PiercedReceiver> pierced_receivers(const Scene &scene, const FrameGeometry &frame,
                                               std::size_t caster,
                                               const glm::vec3 &light_position,
                                               const std::optional<glm::vec4> &caster_plane) {
  std::vector<PiercedReceiver> pierced;
  const SceneObject &object = scene.objects[caster];
  const Mesh &mesh = caster_mesh(object);
  std::vector<glm::vec3> caster_world(mesh.positions.size());
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (std::size_t i = 0; i < caster_world.size(); ++i) {
    caster_world[i] = glm::vec3(object.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
    low = glm::min(low, caster_world[i]), high = glm::max(high, caster_world[i]);
  }
  if (caster_world.empty()) return pierced;
  // A flat caster shadows nothing on the light's side of its plane, and step 3 clips every
  // receiver to the far side (compute_receiver_coords): the clip is the cut through a receiver
  // that is not planar, exact to the pixel, where a mask by the receiver's surface holds it only
  // to a texel (issue 14: a plate through a cylinder, seen close).
  const bool flat = caster_plane.has_value();
  const float tolerance = 1e-4f * glm::length(high - low);
  for (std::size_t r = 0; r < frame.objects.size(); ++r) {
    if (r == caster || !scene.objects[r].receives_shadow) continue;
    glm::vec4 plane;
    if (!planar_receiver(frame.objects[r], light_position, plane)) {
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
