// Stencil shadow volumes, the geometry: the volumes extruded from the casters' silhouettes
// (edge_mesh.h finds them), the test that picks z-fail and the one whether the camera may see
// inside a caster. Spaces: world (the light, the
// casters' world positions, the bounding spheres); homogeneous world relative to the camera's
// position, w = 0 at infinity (the volumes).
#include "techniques/stencil_volume/stencil_volume_geometry.h"

#include "techniques/geometry/point_in_mesh.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gs {
namespace {

// Whether `probe` may touch the shadow volume that `caster` casts from a point light at `light`.
// Every point of the volume lies on a ray from the light through a caster point, beyond it: in
// the cone around the sphere, no nearer the light than the sphere's nearest point.
bool may_touch_volume(const glm::vec3 &light, const Sphere &caster, const Sphere &probe) {
  const glm::vec3 to_caster = caster.centre - light, to_probe = probe.centre - light;
  const float caster_distance = glm::length(to_caster), probe_distance = glm::length(to_probe);
  if (caster_distance <= caster.radius || probe_distance <= probe.radius) return true;
  if (probe_distance + probe.radius < caster_distance - caster.radius) return false;
  const float cone = std::asin(caster.radius / caster_distance);
  const float spread = std::asin(probe.radius / probe_distance);
  const float angle = std::acos(std::clamp(
      glm::dot(to_caster, to_probe) / (caster_distance * probe_distance), -1.0f, 1.0f));
  return angle <= cone + spread + 1e-4f;  // a margin for the rounding of acos near the edge
}

// A sphere (world) around the camera's near-plane rectangle, large enough to hold the camera
// position too: whatever the camera sees nearest lies in it or beyond it.
Sphere near_plane_bounds(const Scene &scene) {
  const Camera &camera = scene.camera;
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const float half_height = camera.near_plane * std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  const float half_width =
      half_height * static_cast<float>(scene.width) / static_cast<float>(scene.height);
  return Sphere{camera.position + forward * camera.near_plane,
                std::sqrt(camera.near_plane * camera.near_plane + half_width * half_width +
                          half_height * half_height)};
}

}  // namespace

namespace stencil_volume {

bool interior_may_be_seen(const Scene &scene, const Sphere &bounds) {
  const Sphere near_plane = near_plane_bounds(scene);
  return glm::length(bounds.centre - near_plane.centre) <= bounds.radius + near_plane.radius;
}

void build_volumes(const std::vector<Caster> &casters, const glm::vec3 &light,
                   const glm::vec3 &origin, bool caps, std::vector<glm::vec4> &out) {
  out.clear();
  for (const Caster &caster : casters) {
    const std::vector<bool> facing = light_facing(caster.mesh, caster.world, light);
    const auto on = [&](glm::uint i) { return glm::vec4(caster.world[i] - origin, 1.0f); };
    const auto beyond = [&](glm::uint i) { return glm::vec4(caster.world[i] - light, 0.0f); };
    for (const SilhouetteEdge &e : find_silhouette(caster.mesh, facing)) {
      // The side walks the edge against the light-facing triangle, as its neighbour on the
      // volume's surface must for both to face outward.
      out.insert(out.end(), {on(e.to), on(e.from), beyond(e.from),
                             on(e.to), beyond(e.from), beyond(e.to)});
    }
    if (!caps) continue;
    // The far cap is the triangles facing away from the light, sent to infinity. The near cap is
    // the same triangles where they are, turned round to face the light: their rims are the
    // silhouette, so the volume is closed, and it holds what lies behind the caster's dark side.
    // (The light-facing triangles would close it as well, but they lie on the caster's lit
    // surface, and wherever the drawn surface is not exactly that mesh - a simplified
    // shadow_mesh, or depths rounded differently - the lit surface would land inside its own
    // volume and be counted in shadow. The dark side is never lit, whatever the count says.)
    // Such a volume counts, at a point, the times the segment from the light leaves the caster
    // (crosses a triangle facing away), so what lies inside the caster is outside it, though
    // the light reaches it only through the caster's lit side. Where the camera may see inside
    // (from within, or through the near plane), the near cap is the light-facing triangles
    // instead: the volume counts the times the segment enters the caster, and holds its inside
    // too. Not when the caster surrounds the light: the segment leaves before it enters, and
    // counting the exits is right, inside lit and beyond dark.
    const bool holds_inside =
        caster.inside_seen && !mesh_surrounds(caster.world, caster.mesh.triangles, light);
    for (std::size_t t = 0; t < caster.mesh.triangles.size(); ++t) {
      const glm::uvec3 &c = caster.mesh.triangles[t];
      if (facing[t]) {
        if (holds_inside) out.insert(out.end(), {on(c.x), on(c.y), on(c.z)});
        continue;
      }
      if (!holds_inside) out.insert(out.end(), {on(c.x), on(c.z), on(c.y)});
      out.insert(out.end(), {beyond(c.x), beyond(c.y), beyond(c.z)});
    }
  }
}

}  // namespace stencil_volume

bool near_plane_may_be_in_shadow(const Scene &scene, const SpotLight &light) {
  const Sphere near_plane = near_plane_bounds(scene);
  for (const SceneObject &object : scene.objects) {
    if (!object.casts_shadow || caster_mesh(object).triangles.empty()) continue;
    if (may_touch_volume(light.position, caster_bounds(object), near_plane)) return true;
  }
  return false;
}

}  // namespace gs
