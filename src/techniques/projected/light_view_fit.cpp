// Step 1's camera: the light's view fitted to one caster (the article's bounding-sphere view, or
// the caster clipped to the light's beam; a closed caster around the light drawn from both sides,
// or refused when a receiver reaches inside it), split into 256x256 tiles above a Voodoo 1
// texture, and the texture size picked from the caster's size on screen (and the note of one
// grown to an accepted size, ProjectedShadowOptions::grow_to_accepted). Spaces: world in; light
// view (the light at the origin looking down -z) and light clip (GL convention) out, as
// LightView's matrices and caster planes (light view space).
#include "techniques/projected/projected_shadow.h"

#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/point_in_mesh.h"
#include "techniques/geometry/edge_mesh.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace gs {
namespace {

constexpr float kWidestHalfView = 80.0f * 3.14159265f / 180.0f;  // beyond, texels stretch 30 times

glm::vec3 up_for(const glm::vec3 &axis) {
  return std::abs(axis.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
}

int screen_size_texture(const Scene &scene, const Sphere &caster) {
  // The caster's diameter on screen in pixels, rounded up to a power of two: the article's LOD.
  const float distance = std::max(glm::length(caster.centre - scene.camera.position), 1e-3f);
  const float half_height = std::tan(glm::radians(scene.camera.fov_degrees) * 0.5f) * distance;
  const float diameter_pixels = caster.radius / half_height * static_cast<float>(scene.height);
  int size = 32;
  while (size < 512 && static_cast<float>(size) < diameter_pixels) size *= 2;
  return size;
}

// The caster's triangles (world) clipped to the beam's outer pyramid and a plane `margin` in front
// of the light (light_beam.h): every point of the caster that can shadow anything the light
// reaches. `whole` says whether nothing was cut off.
std::vector<glm::vec3> caster_in_beam(const SceneObject &object, const LightBeam &beam,
                                      float margin, bool &whole) {
  const Mesh &mesh = caster_mesh(object);
  std::vector<glm::vec3> world(mesh.positions.size());
  for (std::size_t i = 0; i < world.size(); ++i) {
    world[i] = glm::vec3(object.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
  }
  return clip_to_beam(world, mesh.triangles, beam, margin, whole);
}

// The smallest square view from `position` along `axis` that holds every point: the largest
// tangent |x| / -z or |y| / -z; infinite when a point is not in front of the light.
float widest_tangent(const glm::vec3 &position, const glm::vec3 &axis,
                     const std::vector<glm::vec3> &points, float &front, float &back) {
  const glm::mat4 view = glm::lookAt(position, position + axis, up_for(axis));
  float widest = 0.0f;
  front = INFINITY, back = 0.0f;
  for (const glm::vec3 &p : points) {
    const glm::vec3 v = glm::vec3(view * glm::vec4(p, 1.0f));
    if (!(-v.z > 0.0f)) return INFINITY;
    widest = std::max(widest, std::max(std::abs(v.x), std::abs(v.y)) / -v.z);
    front = std::min(front, -v.z);
    back = std::max(back, -v.z);
  }
  return widest;
}

// A closed caster around the light (inside its bounding sphere first, the cheap test) blocks
// everything the light reaches beyond it, and nothing inside it. The texture, drawn from both
// sides, then holds the whole beam: right for receivers outside the caster, wrong for one inside.
// Returns the name of a receiver with a triangle inside the caster's world bounding box (the
// caster cannot serve it), "" when none has; `surrounds` says whether the caster is around the light.
std::string receiver_inside_caster_around_light(const Scene &scene, std::size_t caster,
                                                const glm::vec3 &light, const Sphere &bounds,
                                                bool &surrounds) {
  surrounds = false;
  const SceneObject &object = scene.objects[caster];
  if (glm::length(light - bounds.centre) > bounds.radius) return "";
  const Mesh &mesh = caster_mesh(object);
  if (!is_closed_surface(mesh)) return "";
  std::vector<glm::vec3> world(mesh.positions.size());
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (std::size_t i = 0; i < world.size(); ++i) {
    world[i] = glm::vec3(object.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
    low = glm::min(low, world[i]), high = glm::max(high, world[i]);
  }
  surrounds = mesh_surrounds(world, mesh.triangles, light);
  if (!surrounds) return "";
  for (std::size_t r = 0; r < scene.objects.size(); ++r) {
    const SceneObject &receiver = scene.objects[r];
    if (r == caster || !receiver.receives_shadow) continue;
    std::vector<glm::vec3> corners(receiver.mesh.positions.size());
    for (std::size_t i = 0; i < corners.size(); ++i)
      corners[i] = glm::vec3(receiver.model_to_world * glm::vec4(receiver.mesh.positions[i], 1.0f));
    for (const glm::uvec3 &t : receiver.mesh.triangles) {
      const glm::vec3 t_low = glm::min(corners[t.x], glm::min(corners[t.y], corners[t.z]));
      const glm::vec3 t_high = glm::max(corners[t.x], glm::max(corners[t.y], corners[t.z]));
      if (glm::all(glm::lessThanEqual(t_low, high)) && glm::all(glm::lessThanEqual(low, t_high)))
        return receiver.name;
    }
  }
  return "";
}

}  // namespace

LightView fit_light_view(const Scene &scene, std::size_t caster, std::size_t light_index,
                         const ProjectedShadowOptions &options) {
  const SceneObject &object = scene.objects[caster];
  const SpotLight &light = scene.lights[light_index];
  const Sphere sphere = caster_bounds(object);
  const std::string names =
      "light " + std::to_string(light_index) + " and '" + object.name + "'";
  LightView view;
  view.position = light.position;
  view.size = options.auto_size  ? screen_size_texture(scene, sphere)
              : options.size > 0 ? options.size
                                 : light.shadow_size;
  if (view.size < 32 || view.size > 512 || (view.size & (view.size - 1)) != 0) {
    view.problem = "shadow size " + std::to_string(view.size) + " for light " +
                   std::to_string(light_index) + " is not a power of two in 32..512, so '" +
                   object.name + "' casts no shadow from it";
    return view;
  }
  const std::string inside =
      receiver_inside_caster_around_light(scene, caster, light.position, sphere, view.surrounds_light);
  if (!inside.empty()) {
    view.problem = names + ": the light is inside the caster and '" + inside +
                   "' reaches inside it too; one shadow texture cannot tell what the caster "
                   "surrounds from what lies beyond it, so " + kCastsNoShadow;
    return view;
  }
  const LightBeam beam = light_beam(light);
  view.beam = beam;
  // The view keeps `border_texels` (plus one for the 1/16-pixel snap and bilinear's reach) clean
  // on every side: the Figure 12/13 bug cannot occur.
  const float usable = 1.0f - 2.0f * static_cast<float>(options.border_texels + 1) /
                                  static_cast<float>(view.size);
  const float reach = glm::length(sphere.centre - light.position) + sphere.radius;
  bool whole = false;
  const std::vector<glm::vec3> points =
      caster_in_beam(object, beam, std::max(reach, 1e-6f) * 1e-4f, whole);
  if (points.empty()) {
    view.outside_beam = true;  // its shadow would fall where the light does not shine
    return view;
  }
  view.caster_distance = glm::length(sphere.centre - light.position);
  const float sine = sphere.radius / std::max(view.caster_distance, 1e-6f);
  const float sphere_half = sine < 1.0f ? std::atan(std::tan(std::asin(sine)) / usable) : INFINITY;
  if (whole && sphere_half < kWidestHalfView) {
    // The article's view: the whole caster is in the beam, and its bounding sphere fits.
    view.view = glm::lookAt(light.position, sphere.centre,
                            up_for(glm::normalize(sphere.centre - light.position)));
    view.caster_front = view.caster_distance - sphere.radius;
    const float near_plane = std::max(view.caster_front * 0.5f, 1e-3f);
    view.projection = glm::perspective(2.0f * sphere_half, 1.0f, near_plane,
                                       view.caster_distance + sphere.radius * 1.01f);
    view.usable = true;
    return view;
  }
  // What the beam holds of the caster, seen along the axis of (about) the narrowest cone around
  // it: the directions' mean moved towards the farthest one with shrinking steps (Badoiu and
  // Clarkson's core-set iteration), or the light's own axis if that is narrower.
  std::vector<glm::vec3> directions;
  directions.reserve(points.size());
  glm::vec3 sum(0.0f);
  for (const glm::vec3 &p : points) {
    const glm::vec3 d = p - light.position;
    const float length = glm::length(d);
    if (length > 0.0f) directions.push_back(d / length), sum += directions.back();
  }
  glm::vec3 axis = glm::length(sum) > 1e-6f ? glm::normalize(sum) : beam.axis;
  for (int step = 1; step <= 64 && !directions.empty(); ++step) {
    const glm::vec3 *farthest = &directions.front();
    for (const glm::vec3 &d : directions) {
      if (glm::dot(d, axis) < glm::dot(*farthest, axis)) farthest = &d;
    }
    const glm::vec3 moved = axis + (*farthest - axis) / static_cast<float>(step + 1);
    if (!(glm::length(moved) > 1e-6f)) break;
    axis = glm::normalize(moved);
  }
  float front = 0.0f, back = 0.0f, front_axis = 0.0f, back_axis = 0.0f;
  float widest = widest_tangent(light.position, axis, points, front, back);
  const float widest_axis = widest_tangent(light.position, beam.axis, points, front_axis, back_axis);
  if (widest_axis < widest) widest = widest_axis, axis = beam.axis, front = front_axis, back = back_axis;
  const float half_view = std::atan(widest / usable);
  if (!(half_view < kWidestHalfView)) {
    view.problem =
        names + ": no single projection holds the caster as the light sees it (it would need a " +
        (std::isfinite(half_view) ? std::to_string(static_cast<int>(std::ceil(glm::degrees(2.0f * half_view)))) +
                                        " degree"
                                  : std::string("more than 180 degree")) +
        " view, the widest is " + std::to_string(static_cast<int>(glm::degrees(2.0f * kWidestHalfView))) +
        "), so " + kCastsNoShadow;
    return view;
  }
  view.view = glm::lookAt(light.position, light.position + axis, up_for(axis));
  view.caster_front = front;
  view.caster_distance = 0.5f * (front + back);
  const float near_plane = std::max(front * 0.5f, back * 1e-5f);
  view.projection = glm::perspective(2.0f * half_view, 1.0f, near_plane, back * 1.01f);
  // Step 1 draws only what lies inside the clean border and in front of the near plane: the rest
  // of the caster is outside the beam, and drawn it would soil the border that clamping repeats.
  for (const glm::vec4 &side : {glm::vec4(-1, 0, 0, usable), glm::vec4(1, 0, 0, usable),
                                glm::vec4(0, -1, 0, usable), glm::vec4(0, 1, 0, usable),
                                glm::vec4(0, 0, 1, 1)}) {
    view.caster_planes.push_back(glm::transpose(view.projection) * side);
  }
  view.usable = true;
  return view;
}

std::string grown_shadow_note(const std::string &reason, int size) {
  return reason + "; its shadow is drawn at " + std::to_string(size) +
         " texels instead (grow to the accepted size)";
}

int drawn_shadow_size(const std::vector<DrawnShadowSize> &sizes, std::size_t light,
                      std::size_t caster) {
  for (const DrawnShadowSize &drawn : sizes) {
    if (drawn.light == light && drawn.caster == caster) return drawn.size;
  }
  return 0;
}

std::vector<LightView> split_into_textures(const LightView &view) {
  constexpr int kLargest = 256;  // GR_LOD_256
  if (view.size <= kLargest) return {view};
  const int tiles = view.size / kLargest;  // per side
  std::vector<LightView> parts;
  // The whole map's seams as light view space planes: x_ndc >= c, with c = -1 + 2 k / tiles
  // exact in binary, is (1, 0, 0, -c) in clip space; the neighbour keeps its negation.
  const glm::mat4 to_view = glm::transpose(view.projection);
  auto seam = [&](int axis, int k, float side) {
    glm::vec4 clip_plane(0.0f);
    clip_plane[axis] = side;
    clip_plane.w = -side * (-1.0f + 2.0f * static_cast<float>(k) / static_cast<float>(tiles));
    return to_view * clip_plane;
  };
  for (int ty = 0; ty < tiles; ++ty) {
    for (int tx = 0; tx < tiles; ++tx) {
      // Light clip space remapped so this tile's square of NDC becomes [-1, 1]^2 (rows from the
      // top, as texture rows run): x' = tiles x + (tiles - 1 - 2 tx) w, likewise y.
      glm::mat4 remap(1.0f);
      remap[0][0] = remap[1][1] = static_cast<float>(tiles);
      remap[3][0] = static_cast<float>(tiles - 1 - 2 * tx);
      remap[3][1] = -static_cast<float>(tiles - 1 - 2 * ty);
      LightView part = view;
      part.projection = remap * view.projection;
      part.size = kLargest;
      // Columns' seams first, then rows': in a 2x2 split (a 512 map, the largest) two tiles
      // sharing a row seam share their column, so both cut the same pieces. The outer sides
      // need no cut: the clean border lies beyond them.
      if (tx > 0) part.tile_planes.push_back(seam(0, tx, 1.0f));
      if (tx + 1 < tiles) part.tile_planes.push_back(seam(0, tx + 1, -1.0f));
      // Texture row ty holds NDC y from 1 - 2 ty / tiles down to 1 - 2 (ty + 1) / tiles.
      if (ty > 0) part.tile_planes.push_back(seam(1, tiles - ty, -1.0f));
      if (ty + 1 < tiles) part.tile_planes.push_back(seam(1, tiles - ty - 1, 1.0f));
      parts.push_back(part);
    }
  }
  return parts;
}

}  // namespace gs
