// Ground truth by ray casting with Embree 3: one BVH over every object's world-space triangles,
// a camera ray per pixel centre that sees front faces only (the techniques cull back faces), hit
// points refined in double on the hit triangle's plane, and shadow rays to every spotlight.
// The scene's flags are honoured as every technique honours them: only objects with
// casts_shadow block a shadow ray (themselves included), and a surface whose object has
// receives_shadow false is never in shadow (every light that reaches it is Lit).
#include "measure/ground_truth.h"

#include "scene/lighting.h"
#include "scene/local_origin.h"
#include "techniques/geometry/projection.h"
#include "scene/slides.h"
#include "scene/spotlight.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace gs {
namespace {

// The loader's cap on the screen (scene_file.cpp): no technique renders anything larger.
constexpr int kMaxScreenSide = 2048;
// Shadow rays start this far (times the scene's radius) off the surface, on the lit side.
constexpr double kOffsetScale = 1e-4;
// Twice a triangle's area below this (times the scene's radius squared) makes it degenerate.
constexpr double kDegenerateScale = 1e-12;

// One object as Embree sees it: its kept (non-degenerate) triangles in world space, double.
struct Body {
  int object = -1;
  bool casts = true;                 // the object's casts_shadow: it blocks shadow rays
  bool receives = true;              // the object's receives_shadow
  std::vector<glm::dvec3> position;  // world, per vertex
  std::vector<glm::vec3> normal;     // world, unit, per vertex (shading)
  std::vector<glm::vec3> color;      // 0..1, per vertex
  std::vector<glm::uvec3> triangle;  // indices into the arrays above, by Embree primID
  std::vector<glm::dvec3> face;      // world, unit, CCW-from-outside side, by primID
};

// A shadow ray's context: its filter drops hits on objects that cast no shadow and, unless
// `skip` is RTC_INVALID_GEOMETRY_ID, on that one geometry (the receiver's own object). Embree
// hands the filter the context pointer, so the extra field rides along.
struct SkipGeometryContext {
  RTCIntersectContext base;
  unsigned skip;
};

// Camera rays: drops triangles seen edge-on or from behind, as back-face culling does.
void front_faces_only(const RTCFilterFunctionNArguments *args) {
  const Body &body = *static_cast<const Body *>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const glm::dvec3 &n = body.face[RTCHitN_primID(args->hit, args->N, i)];
    const glm::dvec3 dir(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                         RTCRayN_dir_z(args->ray, args->N, i));
    if (glm::dot(n, dir) >= 0.0) args->valid[i] = 0;
  }
}

void skip_geometry(const RTCFilterFunctionNArguments *args) {
  const unsigned skip = reinterpret_cast<const SkipGeometryContext *>(args->context)->skip;
  const bool casts = static_cast<const Body *>(args->geometryUserPtr)->casts;
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    if (!casts || RTCHitN_geomID(args->hit, args->N, i) == skip) args->valid[i] = 0;
  }
}

// Releases the device and scene on every return path.
struct EmbreeHandles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~EmbreeHandles() {
    if (scene != nullptr) rtcReleaseScene(scene);
    if (device != nullptr) rtcReleaseDevice(device);
  }
};

bool finite(const glm::dvec3 &v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// World-space bodies of every object and the radius of their bounding box (for the epsilons).
std::vector<Body> make_bodies(const Scene &scene, double &radius) {
  std::vector<Body> bodies;
  glm::dvec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject &object = scene.objects[o];
    const Mesh &mesh = object.mesh;
    const glm::dmat4 model(object.model_to_world);
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(object.model_to_world)));
    Body body;
    body.object = static_cast<int>(o);
    body.casts = object.casts_shadow;
    body.receives = object.receives_shadow;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::dvec3 p(model * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
      body.position.push_back(p);
      const bool has_normal = i < mesh.normals.size();
      body.normal.push_back(has_normal ? glm::normalize(normal_matrix * mesh.normals[i])
                                       : glm::vec3(0.0f));
      body.color.push_back(i < mesh.colors.size() ? mesh.colors[i] : glm::vec3(1.0f));
      if (finite(p)) low = glm::min(low, p), high = glm::max(high, p);
    }
    bodies.push_back(std::move(body));
  }
  radius = high.x >= low.x ? 0.5 * glm::length(high - low) : 1.0;
  radius = std::max(radius, 1e-6);  // a single point still needs non-zero epsilons
  const double min_area = kDegenerateScale * radius * radius;
  for (std::size_t o = 0; o < bodies.size(); ++o) {
    Body &body = bodies[o];
    for (const glm::uvec3 &t : scene.objects[o].mesh.triangles) {
      if (t.x >= body.position.size() || t.y >= body.position.size() ||
          t.z >= body.position.size())
        continue;
      const glm::dvec3 &a = body.position[t.x], &b = body.position[t.y], &c = body.position[t.z];
      const glm::dvec3 cross = glm::cross(b - a, c - a);
      const double twice_area = glm::length(cross);
      if (!(twice_area > min_area) || !finite(a) || !finite(b) || !finite(c)) continue;
      body.triangle.push_back(t);
      body.face.push_back(cross / twice_area);
    }
  }
  return bodies;
}

// Adds the bodies with triangles to `handles.scene`; geometry IDs are the indices in `bodies`
// whose triangles are not empty (`by_geometry` maps them back). Embree holds floats, so its
// vertices are in local coordinates (world minus `origin`, the scene's local origin, taken in
// double): 3.6 km from the world's origin floats are 0.24 mm apart, a quarter of
// the shadow rays' offset off the surface in a 10 m scene (local_origin.h).
bool attach_bodies(EmbreeHandles &handles, std::vector<Body> &bodies, const glm::dvec3 &origin,
                   std::vector<const Body *> &by_geometry, std::string &error) {
  for (Body &body : bodies) {
    if (body.triangle.empty()) continue;
    RTCGeometry geometry = rtcNewGeometry(handles.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (geometry == nullptr) {
      error = "ground truth: Embree could not create a geometry";
      return false;
    }
    auto *vertices = static_cast<float *>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
        body.position.size()));
    auto *indices = static_cast<unsigned *>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
        body.triangle.size()));
    if (vertices == nullptr || indices == nullptr) {
      rtcReleaseGeometry(geometry);
      error = "ground truth: Embree could not allocate the buffers of " +
              std::to_string(body.triangle.size()) + " triangles";
      return false;
    }
    for (std::size_t i = 0; i < body.position.size(); ++i) {
      // Non-finite vertices are only referenced by dropped triangles; keep Embree's bounds sane.
      const glm::vec3 p =
          finite(body.position[i]) ? glm::vec3(body.position[i] - origin) : glm::vec3(0.0f);
      vertices[3 * i] = p.x, vertices[3 * i + 1] = p.y, vertices[3 * i + 2] = p.z;
    }
    for (std::size_t i = 0; i < body.triangle.size(); ++i) {
      indices[3 * i] = body.triangle[i].x;
      indices[3 * i + 1] = body.triangle[i].y;
      indices[3 * i + 2] = body.triangle[i].z;
    }
    rtcSetGeometryUserData(geometry, &body);
    rtcCommitGeometry(geometry);
    by_geometry.push_back(&body);
    rtcAttachGeometryByID(handles.scene, geometry, static_cast<unsigned>(by_geometry.size() - 1));
    rtcReleaseGeometry(geometry);  // the scene holds it now
  }
  return true;
}

// A ray from `start` (world) along `dir`, its start moved to Embree's local coordinates (minus
// `origin`, the vertices' local origin) in double before it is rounded to float.
RTCRay make_ray(const glm::dvec3 &start, const glm::dvec3 &origin, const glm::dvec3 &dir,
                double tfar) {
  RTCRay ray;
  const glm::vec3 local(start - origin);
  ray.org_x = local.x;
  ray.org_y = local.y;
  ray.org_z = local.z;
  ray.dir_x = static_cast<float>(dir.x);
  ray.dir_y = static_cast<float>(dir.y);
  ray.dir_z = static_cast<float>(dir.z);
  ray.tnear = 0.0f;
  ray.tfar = static_cast<float>(tfar);
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

// Everything the per-pixel work reads; shared read-only by the threads.
struct Caster {
  const Scene &scene;
  RTCScene rtc;
  const std::vector<const Body *> &by_geometry;
  glm::dmat4 screen_to_world;  // inverse of camera projection * view, NDC to world
  double offset;               // world, how far a shadow ray starts off the surface
  glm::dvec3 origin;           // world, the local origin of Embree's vertices and rays
  std::vector<ProjectedImage> slides;  // per light: its slide, empty unless a projector
};

// Whether a face turns towards the light, decided per face as the techniques decide it (edge-on
// is away): against one of its corners, not the hit point, whose rounding off the plane would
// make a light lying in the face's plane light a random scatter of its pixels.
bool faces_light(const glm::dvec3 &face, const glm::dvec3 &corner, const glm::dvec3 &light) {
  return glm::dot(face, light - corner) > 0.0;
}

// Whether `light` reaches the surface point (on the face through `corner`), and if blocked,
// whether another object blocks it. Only casters block; a surface that receives no shadow is
// lit wherever the light reaches it.
LightReach reach_light(const Caster &c, const SpotLight &light, const glm::dvec3 &point,
                       const glm::dvec3 &face, const glm::dvec3 &corner, unsigned own,
                       bool receives, bool &by_other) {
  by_other = false;
  const glm::dvec3 light_pos(light.position);
  if (spot_factor(light, glm::vec3(point)) <= 0.0f || !faces_light(face, corner, light_pos))
    return LightReach::Outside;
  if (!receives) return LightReach::Lit;
  // The shadow ray starts on the segment from the point to the light, so it tests that segment
  // and nothing beside it: a start moved along the face's normal instead could step across a
  // nearby caster's edge (a forearm a fraction of a millimetre from its glove's shadow boundary
  // was called lit). Far enough along to stand `offset` off the face's plane (at most four
  // offsets along the segment, for a grazing light), plus a hundredth of an offset along the
  // normal so that a light in the face's plane cannot re-hit the face.
  const double reach = glm::length(light_pos - point);
  if (reach <= c.offset) return LightReach::Lit;  // a light on the surface: nothing between
  const glm::dvec3 toward = (light_pos - point) / reach;
  const double along = c.offset / std::max(glm::dot(face, toward), 0.25);
  const glm::dvec3 origin = point + toward * along + face * (0.01 * c.offset);
  const glm::dvec3 to_light = light_pos - origin;
  const double distance = glm::length(to_light);
  // Stop one offset short of the light: a light sitting on a surface is not blocked by it.
  const double tfar = distance - c.offset;
  if (tfar <= 0.0) return LightReach::Lit;
  SkipGeometryContext others;
  rtcInitIntersectContext(&others.base);
  others.base.filter = skip_geometry;
  others.skip = own;
  RTCRay ray = make_ray(origin, c.origin, to_light / distance, tfar);
  rtcOccluded1(c.rtc, &others.base, &ray);
  if (ray.tfar < 0.0f) {
    by_other = true;
    return LightReach::Blocked;
  }
  SkipGeometryContext any;  // every caster, the receiver's own object included
  rtcInitIntersectContext(&any.base);
  any.base.filter = skip_geometry;
  any.skip = RTC_INVALID_GEOMETRY_ID;
  ray = make_ray(origin, c.origin, to_light / distance, tfar);
  rtcOccluded1(c.rtc, &any.base, &ray);
  return ray.tfar < 0.0f ? LightReach::Blocked : LightReach::Lit;
}

std::uint8_t to_byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

void cast_pixel(const Caster &c, int i, int j, GroundTruth &truth) {
  const Scene &scene = c.scene;
  const std::size_t pixel = static_cast<std::size_t>(j) * scene.width + i;
  const std::size_t lights = scene.lights.size();
  // Pixel centre in NDC: x right, y up (Glide rows run from the top).
  const double x = (i + 0.5) / scene.width * 2.0 - 1.0;
  const double y = 1.0 - (j + 0.5) / scene.height * 2.0;
  const glm::dvec4 near_h = c.screen_to_world * glm::dvec4(x, y, -1.0, 1.0);
  const glm::dvec4 far_h = c.screen_to_world * glm::dvec4(x, y, 1.0, 1.0);
  const glm::dvec3 origin = glm::dvec3(near_h) / near_h.w;  // on the near plane, as clipping does
  const glm::dvec3 span = glm::dvec3(far_h) / far_h.w - origin;
  const double length = glm::length(span);
  const glm::dvec3 dir = span / length;

  RTCIntersectContext front;
  rtcInitIntersectContext(&front);
  front.filter = front_faces_only;
  RTCRayHit hit;
  hit.ray = make_ray(origin, c.origin, dir, length);
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(c.rtc, &front, &hit);

  std::uint8_t *rgb = &truth.rgb[3 * pixel];
  if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
    rgb[0] = to_byte(scene.background.r), rgb[1] = to_byte(scene.background.g);
    rgb[2] = to_byte(scene.background.b);
    return;  // object -1, every light Outside, no shadow: the defaults
  }
  const Body &body = *c.by_geometry[hit.hit.geomID];
  const glm::uvec3 &tri = body.triangle[hit.hit.primID];
  const glm::dvec3 &face = body.face[hit.hit.primID];
  truth.object[pixel] = body.object;

  // Embree's t is single precision; the plane of the hit triangle gives the point in double.
  const double facing = glm::dot(face, dir);
  const double t = facing < 0.0 ? glm::dot(face, body.position[tri.x] - origin) / facing
                                : static_cast<double>(hit.ray.tfar);
  const glm::dvec3 point = origin + dir * t;
  const float u = hit.hit.u, v = hit.hit.v, w = 1.0f - u - v;  // weights of vertices y, z, x
  const glm::vec3 albedo = body.color[tri.x] * w + body.color[tri.y] * u + body.color[tri.z] * v;
  glm::vec3 normal = body.normal[tri.x] * w + body.normal[tri.y] * u + body.normal[tri.z] * v;
  // Shading uses the interpolated vertex normal, as the scene pass does; a mesh without
  // normals (or with ones that cancel) falls back to the face.
  normal = glm::length(normal) > 1e-6f ? glm::normalize(normal) : glm::vec3(face);

  glm::vec3 light_sum = scene.ambient;
  bool by_other_any = false, by_self_only_any = false;
  for (std::size_t l = 0; l < lights; ++l) {
    const SpotLight &light = scene.lights[l];
    if (light.is_projector()) {
      // The slide's colour where the projector sees a surface facing it (Segal et al.'s pass 2,
      // which ignores occlusion); it casts no shadow, so the light's reach stays Outside.
      glm::vec2 uv;
      if (faces_light(face, body.position[tri.x], glm::dvec3(light.position)) &&
          beam_coordinates(light, glm::vec3(point), uv))
        light_sum += light.color * sample_projected_image(c.slides[l], uv);
      continue;
    }
    bool by_other = false;
    const LightReach reach =
        reach_light(c, light, point, face, body.position[tri.x], hit.hit.geomID, body.receives,
                    by_other);
    truth.reach[pixel * lights + l] = reach;
    if (reach == LightReach::Blocked) {
      (by_other ? by_other_any : by_self_only_any) = true;
    } else if (reach == LightReach::Lit) {
      const glm::vec3 p(point);
      const glm::vec3 to_light = glm::normalize(light.position - p);
      light_sum += light.color * (std::max(0.0f, glm::dot(normal, to_light)) *
                                  spot_factor(light, p) *
                                  distance_attenuation(light, axial_distance(light, p)));
    }
  }
  truth.shadow[pixel] = by_other_any ? 1 : 0;
  truth.self_shadow[pixel] = by_self_only_any ? 1 : 0;
  const glm::vec3 color = albedo * light_sum;
  rgb[0] = to_byte(color.r), rgb[1] = to_byte(color.g), rgb[2] = to_byte(color.b);
}

}  // namespace

bool compute_ground_truth(const Scene &scene, GroundTruth &truth, std::string &error) {
  if (scene.width < 1 || scene.height < 1 || scene.width > kMaxScreenSide ||
      scene.height > kMaxScreenSide) {
    error = "ground truth: screen " + std::to_string(scene.width) + "x" +
            std::to_string(scene.height) + " is outside 1.." + std::to_string(kMaxScreenSide);
    return false;
  }
  const glm::dmat4 view_projection = glm::dmat4(camera_projection(scene.camera, scene.width,
                                                                  scene.height)) *
                                     glm::dmat4(camera_view(scene.camera));
  const glm::dmat4 screen_to_world = glm::inverse(view_projection);
  if (!std::isfinite(glm::determinant(screen_to_world))) {
    error = "ground truth: the camera's view and projection cannot be inverted";
    return false;
  }

  double radius = 1.0;
  std::vector<Body> bodies = make_bodies(scene, radius);
  EmbreeHandles handles;
  // One build thread: the BVH, and so any tie between equal hits, is the same on every run.
  handles.device = rtcNewDevice("threads=1");
  if (handles.device == nullptr) {
    error = "ground truth: no Embree device (error " +
            std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")";
    return false;
  }
  handles.scene = rtcNewScene(handles.device);
  rtcSetSceneFlags(handles.scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(handles.scene, RTC_BUILD_QUALITY_HIGH);
  std::vector<const Body *> by_geometry;
  const glm::dvec3 origin(local_origin(scene));
  if (!attach_bodies(handles, bodies, origin, by_geometry, error)) return false;
  rtcCommitScene(handles.scene);
  if (rtcGetDeviceError(handles.device) != RTC_ERROR_NONE) {
    error = "ground truth: Embree could not build the scene";
    return false;
  }

  GroundTruth out;
  out.width = scene.width, out.height = scene.height;
  out.lights = scene.lights.size();
  const std::size_t pixels = static_cast<std::size_t>(scene.width) * scene.height;
  out.object.assign(pixels, -1);
  out.reach.assign(pixels * out.lights, LightReach::Outside);
  out.shadow.assign(pixels, 0);
  out.self_shadow.assign(pixels, 0);
  out.rgb.assign(pixels * 3, 0);

  Caster caster{scene, handles.scene, by_geometry, screen_to_world, kOffsetScale * radius,
                origin, {}};
  for (const SpotLight &light : scene.lights)
    caster.slides.push_back(light.is_projector() ? slide_image(light) : ProjectedImage{});
  // Threads take rows from a counter; every pixel depends only on its own ray, so the bytes are
  // the same whatever the thread count or the order rows are taken in.
  std::atomic<int> next_row{0};
  auto work = [&] {
    for (int j = next_row++; j < scene.height; j = next_row++) {
      for (int i = 0; i < scene.width; ++i) cast_pixel(caster, i, j, out);
    }
  };
  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 64u);
  std::vector<std::thread> pool;
  for (unsigned k = 1; k < threads; ++k) pool.emplace_back(work);
  work();
  for (std::thread &thread : pool) thread.join();

  truth = std::move(out);
  return true;
}

}  // namespace gs
