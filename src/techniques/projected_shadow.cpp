// The projected shadow texture, step by step. Spaces: world; light view (the light at the
// origin looking down -z); light clip (GL convention); Glide screen (pixels, y down) for both
// the light's size x size view in step 1 and the camera in steps 4-5; Glide texture units
// (s, t in 0..256 across the shadow texture).
#include "techniques/projected_shadow.h"

#include "techniques/light_beam.h"
#include "techniques/stencil_volume_shadow.h"

#include <glide_shim.h>
#include <glideutl.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace gs {
namespace {

constexpr GrColor_t kShadowRedArgb = 0x00F00000u;  // red 240: the 565 red field 11110b




GrLOD_t lod_for(int size) {
  GrLOD_t lod = GR_LOD_256;
  for (int side = 256; side > size; side /= 2) ++lod;
  return lod;
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

// (s, t) numerators and divisor of a world point for step 5, in Glide texture units.
glm::vec3 shadow_stq(const LightView &view, const glm::vec3 &world) {
  const glm::vec4 clip = view.projection * view.view * glm::vec4(world, 1.0f);
  return {(0.5f * clip.x + 0.5f * clip.w) * 256.0f, (0.5f * clip.w - 0.5f * clip.y) * 256.0f,
          clip.w};
}

// Whether a receiver polygon, given by its light clip coordinates (all with w > 0), can be in
// the caster's shadow: it must see an occupied cell of the texture (its projection is convex, so
// its bounding box bounds it; one texel of margin covers bilinear filtering's reach) and reach
// beyond the caster's nearest point in that cell.
bool sees_caster(const LightView &view, const glm::vec4 *light_clip, std::size_t count) {
  glm::vec2 low(INFINITY), high(-INFINITY);
  float farthest = 0.0f;
  for (std::size_t i = 0; i < count; ++i) {
    farthest = std::max(farthest, light_clip[i].w);
    const glm::vec2 uv = (glm::vec2(light_clip[i].x, -light_clip[i].y) / light_clip[i].w * 0.5f +
                          0.5f) * static_cast<float>(view.size);  // texels
    low = glm::min(low, uv);
    high = glm::max(high, uv);
  }
  const float cell = static_cast<float>(view.size) / LightView::kCells;
  const int x0 = std::max(0, static_cast<int>(std::floor((low.x - 1.0f) / cell)));
  const int y0 = std::max(0, static_cast<int>(std::floor((low.y - 1.0f) / cell)));
  const int x1 = std::min(LightView::kCells - 1, static_cast<int>(std::floor((high.x + 1.0f) / cell)));
  const int y1 = std::min(LightView::kCells - 1, static_cast<int>(std::floor((high.y + 1.0f) / cell)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const auto index = static_cast<std::size_t>(y * LightView::kCells + x);
      if (view.occupied[index] && farthest > view.nearest[index]) return true;
    }
  }
  return false;
}

float shadow_alpha(const SpotLight &light, const LightView &view, const glm::vec3 &world,
                   ShadowAlpha mode) {
  float alpha = light.shadow_strength * 255.0f;
  if (mode == ShadowAlpha::Distance) {
    // Fainter the farther the receiver is behind the caster, as a wider penumbra would be.
    const float distance = glm::length(world - view.position);
    alpha *= std::clamp(view.caster_distance / std::max(distance, 1e-3f), 0.0f, 1.0f);
  }
  return alpha;
}

// Fills the texture fields of a camera-screen vertex for the world point it stands for.
void set_texture_fields(GrVertex &v, const LightView &view, const SpotLight &light,
                        const glm::vec3 &world, const ProjectedShadowOptions &options) {
  const glm::vec3 stq = shadow_stq(view, world);
  if (options.projective) {
    // The hardware divides per pixel by tmuvtx[0].oow (GR_STWHINT_W_DIFF_TMU0).
    v.tmuvtx[0].sow = stq.x * v.oow;
    v.tmuvtx[0].tow = stq.y * v.oow;
    v.tmuvtx[0].oow = stq.z * v.oow;
  } else {
    // Listing 3: (s, t) divided per vertex, interpolated with the camera's perspective only.
    v.tmuvtx[0].sow = stq.x / stq.z * v.oow;
    v.tmuvtx[0].tow = stq.y / stq.z * v.oow;
  }
  v.a = shadow_alpha(light, view, world, options.alpha);
}

using Clock = std::chrono::steady_clock;
double elapsed_ms(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

namespace {

constexpr float kWidestHalfView = 80.0f * 3.14159265f / 180.0f;  // beyond, texels stretch 30 times

glm::vec3 up_for(const glm::vec3 &axis) {
  return std::abs(axis.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
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
        "), so it casts no shadow from this light";
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

std::vector<LightView> split_into_textures(const LightView &view) {
  constexpr int kLargest = 256;  // GR_LOD_256
  if (view.size <= kLargest) return {view};
  const int tiles = view.size / kLargest;  // per side
  std::vector<LightView> parts;
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
      part.clip_to_view = true;
      parts.push_back(part);
    }
  }
  return parts;
}

void render_caster_from_light(const Scene &scene, std::size_t caster, LightView &view,
                              const ProjectedShadowOptions &options, FxU32 texture_address) {
  const SceneObject &object = scene.objects[caster];
  view.direct_path = options.direct_path;
  if (!view.direct_path && (view.size > scene.width || view.size > scene.height)) {
    view.direct_path = true;
    view.note = "a " + std::to_string(view.size) + "x" + std::to_string(view.size) +
                " shadow texture does not fit in the " + std::to_string(scene.width) + "x" +
                std::to_string(scene.height) + " back buffer; step 1 rendered it into texture "
                "memory directly";
  }
  // The flat render: 565 red 11110b on 0, no depth test, back faces culled (closed casters).
  if (view.direct_path && !glideShimRenderToTexture(GR_TMU0, texture_address, lod_for(view.size))) {
    view.usable = false;
    view.problem = std::string("step 1 cannot render into texture memory: ") +
                   glideShimGetLastErrorMessage();
    return;
  }
  const FxU32 side = static_cast<FxU32>(view.size);
  grClipWindow(0, 0, side, side);
  grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
  grDepthMask(FXFALSE);
  grDitherMode(GR_DITHER_DISABLE);  // a dithered 240 would not always be 11110b
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  // A closed caster's back faces lie inside its front faces' outline; an open one (a tube, a
  // sheet) may show the light only its back, so it is drawn from both sides.
  grCullMode(build_edge_mesh(caster_mesh(object)).closed ? GR_CULL_POSITIVE : GR_CULL_DISABLE);
  grBufferClear(0, 0, 0);
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grConstantColorValue(kShadowRedArgb);
  const glm::mat4 to_view = view.view * object.model_to_world;
  const Mesh &mesh = caster_mesh(object);
  std::vector<GrVertex> screen(mesh.positions.size());
  std::vector<float> depth(mesh.positions.size());  // light-view distance along the axis (w)
  std::vector<glm::vec4> in_view(mesh.positions.size());
  std::vector<bool> inside(mesh.positions.size(), true);
  for (std::size_t i = 0; i < screen.size(); ++i) {
    in_view[i] = to_view * glm::vec4(mesh.positions[i], 1.0f);
    for (const glm::vec4 &plane : view.caster_planes) {
      if (glm::dot(plane, in_view[i]) < 0.0f) inside[i] = false;
    }
    const glm::vec4 clip = view.projection * in_view[i];
    if (inside[i]) screen[i] = to_screen(clip, view.size, view.size);
    depth[i] = clip.w;
  }
  const float cell = static_cast<float>(view.size) / LightView::kCells;  // texels
  auto cell_index = [&](float texels) {
    return std::clamp(static_cast<int>(std::floor(texels / cell)), 0, LightView::kCells - 1);
  };
  // Marks the cells a drawn triangle's bounding box covers, with its nearest depth.
  auto occupy = [&](const GrVertex *const *corners, std::size_t count, float nearest) {
    float x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (std::size_t k = 0; k < count; ++k) {
      x0 = std::min(x0, corners[k]->x), x1 = std::max(x1, corners[k]->x);
      y0 = std::min(y0, corners[k]->y), y1 = std::max(y1, corners[k]->y);
    }
    for (int cy = cell_index(y0); cy <= cell_index(y1); ++cy) {
      for (int cx = cell_index(x0); cx <= cell_index(x1); ++cx) {
        const auto cell_at = static_cast<std::size_t>(cy * LightView::kCells + cx);
        view.occupied[cell_at] = true;
        view.nearest[cell_at] = std::min(view.nearest[cell_at], nearest);
      }
    }
  };
  std::vector<ClipVertex> polygon, scratch;
  std::vector<GrVertex> fan;
  std::vector<const GrVertex *> corners;
  for (const glm::uvec3 &t : mesh.triangles) {
    if (inside[t.x] && inside[t.y] && inside[t.z]) {
      guDrawTriangleWithClip(&screen[t.x], &screen[t.y], &screen[t.z]);  // tiles cut the caster
      const GrVertex *const triangle[3] = {&screen[t.x], &screen[t.y], &screen[t.z]};
      occupy(triangle, 3, std::min({depth[t.x], depth[t.y], depth[t.z]}));
      continue;
    }
    // Partly outside the beam's view: only the part inside is drawn.
    polygon.clear();
    for (unsigned i : {t.x, t.y, t.z}) polygon.push_back({in_view[i], {}, {}});
    for (const glm::vec4 &plane : view.caster_planes) {
      clip_polygon(polygon, plane, scratch);
      if (polygon.size() < 3) break;
    }
    if (polygon.size() < 3) continue;
    fan.clear();
    corners.clear();
    float nearest = INFINITY;
    for (const ClipVertex &v : polygon) {
      const glm::vec4 clip = view.projection * v.clip;
      fan.push_back(to_screen(clip, view.size, view.size));
      nearest = std::min(nearest, clip.w);
    }
    for (const GrVertex &v : fan) corners.push_back(&v);
    draw_fan(fan);
    occupy(corners.data(), corners.size(), nearest);
  }
  if (view.direct_path) glideShimRenderToFrameBuffer();
  grClipWindow(0, 0, static_cast<FxU32>(scene.width), static_cast<FxU32>(scene.height));
}

ShadowTexture make_shadow_texture(const LightView &view, const ProjectedShadowOptions &options,
                                  FxU32 texture_address) {
  ShadowTexture texture;
  texture.address = texture_address;
  texture.info.smallLod = texture.info.largeLod = lod_for(view.size);
  texture.info.aspectRatio = GR_ASPECT_1x1;
  // The same 16-bit words, read as ARGB_4444: alpha is the top nibble of the red field.
  // The chroma-key variant reads them as the colour they were drawn in.
  texture.info.format = options.chroma_key ? GR_TEXFMT_RGB_565 : GR_TEXFMT_ARGB_4444;
  if (view.direct_path) return texture;  // step 1 already wrote texture memory

  const auto side = static_cast<FxU32>(view.size);
  std::vector<FxU16> shadow_bitmap(static_cast<std::size_t>(side) * side);  // system memory
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, side, side, side * 2, shadow_bitmap.data());
  texture.info.data = shadow_bitmap.data();
  grTexDownloadMipMap(GR_TMU0, texture_address, GR_MIPMAPLEVELMASK_BOTH, &texture.info);
  texture.info.data = nullptr;
  return texture;
}

ReceiverCoords compute_receiver_coords(const Scene &scene, const FrameGeometry &frame,
                                       std::size_t caster, const SpotLight &light,
                                       const LightView &view, const ProjectedShadowOptions &options) {
  ReceiverCoords coords;
  const glm::mat4 light_clip = view.projection * view.view;
  // Light view space: the part of a receiver nearer the light than the caster's bounds cannot
  // be in its shadow (and behind the light nothing is): keep -z >= caster_front.
  std::vector<glm::vec4> view_planes = {{0.0f, 0.0f, -1.0f, -view.caster_front}};
  if (view.clip_to_view) {
    // A tile's sides as light-view planes: a clip-space plane p is transpose(P) p in view space.
    for (const glm::vec4 &side : {glm::vec4(-1, 0, 0, 1), glm::vec4(1, 0, 0, 1),
                                  glm::vec4(0, -1, 0, 1), glm::vec4(0, 1, 0, 1)}) {
      view_planes.push_back(glm::transpose(view.projection) * side);
    }
  }
  // The light's inner beam (light_beam.h) in light view space: no shadow outside it.
  const glm::mat4 world_from_view = glm::inverse(view.view);
  std::vector<std::vector<glm::vec4>> beam_regions;
  for (const std::vector<glm::vec4> &region : view.beam.regions) {
    beam_regions.emplace_back();
    for (const glm::vec4 &plane : region) {
      beam_regions.back().push_back(glm::transpose(world_from_view) * plane);
    }
  }
  const LightBeam &beam = view.beam;
  std::vector<ClipVertex> polygon, scratch;
  for (std::size_t r = 0; r < frame.objects.size(); ++r) {
    const ProjectedObject &receiver = frame.objects[r];
    if (r == caster || !receiver.object->receives_shadow) continue;
    const std::size_t n = receiver.world.size();
    std::vector<glm::vec4> lc(n);  // light clip
    std::vector<unsigned> flags(n);
    for (std::size_t i = 0; i < n; ++i) {
      lc[i] = light_clip * glm::vec4(receiver.world[i], 1.0f);
      const glm::vec4 &p = lc[i];
      flags[i] = (p.x < -p.w) | (p.x > p.w) << 1 | (p.y < -p.w) << 2 | (p.y > p.w) << 3 |
                 (p.w < view.caster_front) << 4;
      if (!beam_regions.empty() && !beam.surely_inside(receiver.world[i])) flags[i] |= 0x20;
    }
    for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
      const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
      // Listing 2: skip triangles facing away from the light and those wholly outside its view.
      if (glm::dot(glm::cross(b - a, c - a), light.position - a) <= 0.0f) continue;
      if ((flags[t.x] & flags[t.y] & flags[t.z] & 0x1F) != 0) continue;
      const unsigned any_outside = flags[t.x] | flags[t.y] | flags[t.z];
      const bool in_front = (any_outside & 0x10) != 0;
      const bool beyond_beam = (any_outside & 0x20) != 0;
      const bool needs_clip =
          in_front || beyond_beam || (view.clip_to_view && (any_outside & 0xF) != 0);
      if (!needs_clip) {
        const glm::vec4 corners[3] = {lc[t.x], lc[t.y], lc[t.z]};
        if (!sees_caster(view, corners, 3)) continue;
      }
      const bool exact = !needs_clip &&
                         (receiver.outside[t.x] | receiver.outside[t.y] | receiver.outside[t.z]) == 0;
      if (exact) {
        ShadowTriangle triangle;
        const unsigned index[3] = {t.x, t.y, t.z};
        for (int k = 0; k < 3; ++k) {
          triangle.v[k] = receiver.screen[index[k]];
          set_texture_fields(triangle.v[k], view, light, receiver.world[index[k]], options);
        }
        coords.triangles.push_back(triangle);
        continue;
      }
      polygon.clear();
      for (unsigned i : {t.x, t.y, t.z}) {
        polygon.push_back({view.view * glm::vec4(receiver.world[i], 1.0f), receiver.world[i], {}});
      }
      for (const glm::vec4 &plane : view_planes) {
        clip_polygon(polygon, plane, scratch);
        if (polygon.size() < 3) break;
      }
      if (polygon.size() < 3) continue;
      // Beyond the beam's sure inside: one piece per lit region (light_beam.h).
      const std::size_t pieces = beyond_beam ? beam_regions.size() : 1;
      for (std::size_t piece = 0; piece < pieces; ++piece) {
        std::vector<ClipVertex> part = polygon;
        if (beyond_beam) {
          for (const glm::vec4 &plane : beam_regions[piece]) {
            if (part.size() < 3) break;
            clip_polygon(part, plane, scratch);
          }
        }
        if (part.size() < 3) continue;
        std::vector<glm::vec4> corners;
        for (const ClipVertex &v : part) corners.push_back(view.projection * v.clip);
        if (!sees_caster(view, corners.data(), corners.size())) continue;
        std::vector<GrVertex> screen;
        project_camera_polygon(frame, scene, part, scratch, screen);
        for (std::size_t i = 0; i < screen.size(); ++i) {
          set_texture_fields(screen[i], view, light, part[i].world, options);
        }
        if (screen.size() >= 3) coords.clipped.push_back(std::move(screen));
      }
    }
  }
  return coords;
}

namespace {

// Step 5's state, also used by the mask pass with a different colour path.
void set_shadow_pass_state(const ShadowTexture &texture, const ProjectedShadowOptions &options) {
  GrTexInfo info = texture.info;
  grTexSource(GR_TMU0, texture.address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  const GrTextureFilterMode_t filter = options.bilinear && !options.chroma_key
                                           ? GR_TEXTUREFILTER_BILINEAR
                                           : GR_TEXTUREFILTER_POINT_SAMPLED;
  grTexFilterMode(GR_TMU0, filter, filter);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  grHints(GR_HINT_STWHINT, options.projective ? GR_STWHINT_W_DIFF_TMU0 : 0);
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LEQUAL);
  grDepthMask(FXFALSE);
  grCullMode(GR_CULL_POSITIVE);
  if (options.chroma_key) {
    // Figure 15's alternative: texels of the background colour are rejected outright.
    grChromakeyValue(0);
    grChromakeyMode(GR_CHROMAKEY_ENABLE);
    grAlphaCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
  } else {
    grAlphaCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                   GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  }
}

// Step 5's depth levels, in W-buffer codes nearer than step 4's surfaces (grDepthBiasLevel; 4096
// codes an octave of w, on the Voodoo and in the shim). Each pixel is darkened once per light,
// however many of its casters' shadows overlap there: every pass that darkens also marks the
// pixels it darkened in the depth buffer (nearer), and the next shadow of the same light fails
// the depth test there (GR_CMP_LESS).
//   - Exact triangles (step 4's own screen vertices) darken and mark in one pass at kExactCodes:
//     another exact triangle at the same pixel gives the same depth, which is not less.
//   - Clipped polygons are coplanar with what step 4 drew but not made of the same vertices, so
//     their depth strays from it by up to 4 codes (tests/hard_cases/eye_near_plane.json): they
//     darken at kClippedCodes, then mark kSealCodes nearer with colour writes off (a seal that
//     every later cover on the same surface fails by more than the stray).
// Clipped polygons are drawn first, so an exact triangle after them fails on their seals.
constexpr FxI16 kExactCodes = 1;
constexpr FxI16 kClippedCodes = 9;
constexpr FxI16 kSealCodes = kClippedCodes + 16;

void draw_exact(const ReceiverCoords &receivers) {
  for (const ShadowTriangle &t : receivers.triangles) {
    guDrawTriangleWithClip(&t.v[0], &t.v[1], &t.v[2]);
  }
}

void draw_clipped(const ReceiverCoords &receivers) {
  for (const std::vector<GrVertex> &polygon : receivers.clipped) draw_fan(polygon);
}

void restore_scene_state() {
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  grAlphaTestFunction(GR_CMP_ALWAYS);
  set_scene_state();
}

}  // namespace

namespace {

// Step 5 for the shadows of one light, in order, each pixel darkened once (the depth levels
// above). Leaves marks in the depth buffer, up to kSealCodes nearer than step 4's surfaces.
void render_light_shadow_passes(const std::vector<const ShadowJob *> &jobs,
                                const ProjectedShadowOptions &options) {
  // Black, at texture alpha x iterated alpha, over the lit scene; marks where alpha > 0.
  auto darken = [&](const ShadowJob &job) {
    set_shadow_pass_state(job.texture, options);
    grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ZERO,
                   GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                         GR_BLEND_ZERO);
    grAlphaTestFunction(GR_CMP_GREATER);
    grAlphaTestReferenceValue(0);
    grDepthBufferFunction(GR_CMP_LESS);
  };
  for (const ShadowJob *job : jobs) {
    if (job->receivers.clipped.empty()) continue;
    darken(*job);
    grDepthMask(FXFALSE);
    grDepthBiasLevel(-kClippedCodes);
    draw_clipped(job->receivers);
    grColorMask(FXFALSE, FXFALSE);  // the seal: depth only, where the cover darkened
    grDepthMask(FXTRUE);
    grDepthBiasLevel(-kSealCodes);
    draw_clipped(job->receivers);
    grColorMask(FXTRUE, FXFALSE);
  }
  for (const ShadowJob *job : jobs) {
    darken(*job);
    grDepthMask(FXTRUE);
    grDepthBiasLevel(-kExactCodes);
    draw_exact(job->receivers);
  }
  grDepthBiasLevel(0);
  restore_scene_state();
}

}  // namespace

void render_shadow_pass(const ShadowJob &job, const ProjectedShadowOptions &options) {
  render_light_shadow_passes({&job}, options);
}

ShadowFrame render_projected_shadows(const Scene &scene, const ProjectedShadowOptions &options,
                                     bool synchronous) {
  ShadowFrame result;
  const auto frame_start = Clock::now();
  auto finish_step = [&](int step, Clock::time_point start) {
    if (synchronous) grSstIdle();
    result.times.ms[step] += elapsed_ms(start);
  };
  FrameGeometry frame = project_scene(scene);
  grRenderBuffer(GR_BUFFER_BACKBUFFER);
  FxU32 next_address = grTexMinAddress(GR_TMU0);
  for (std::size_t light = 0; light < scene.lights.size(); ++light) {
    if (scene.lights[light].is_projector()) continue;  // slides cast no shadows
    for (std::size_t caster = 0; caster < scene.objects.size(); ++caster) {
      if (!scene.objects[caster].casts_shadow) continue;
      auto start = Clock::now();
      const LightView fitted = fit_light_view(scene, caster, light, options);  // 1
      result.times.ms[0] += elapsed_ms(start);
      if (!fitted.usable) {
        if (!fitted.outside_beam) result.errors.push_back(fitted.problem);
        continue;
      }
      for (LightView &part : split_into_textures(fitted)) {
        // Each texture takes its own TMU memory; when 2 MB run out, the rest cast nothing.
        GrTexInfo needed{lod_for(part.size), lod_for(part.size), GR_ASPECT_1x1,
                         GR_TEXFMT_ARGB_4444, nullptr};
        if (next_address + grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &needed) >
            grTexMaxAddress(GR_TMU0) + 8) {
          result.errors.push_back("TMU memory is full: '" + scene.objects[caster].name +
                                  "' casts no shadow from light " + std::to_string(light));
          break;
        }
        ShadowJob job;
        job.caster = caster;
        job.light = light;
        job.view = part;
        start = Clock::now();
        render_caster_from_light(scene, caster, job.view, options, next_address);  // 1
        finish_step(0, start);
        if (!job.view.usable) {
          result.errors.push_back(job.view.problem);
          continue;
        }
        if (!job.view.note.empty() &&
            std::find(result.warnings.begin(), result.warnings.end(), job.view.note) ==
                result.warnings.end()) {
          result.warnings.push_back(job.view.note);
        }
        start = Clock::now();
        job.texture = make_shadow_texture(job.view, options, next_address);  // 2
        finish_step(1, start);
        GrTexInfo info = job.texture.info;
        next_address += grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &info);
        start = Clock::now();
        job.receivers = compute_receiver_coords(scene, frame, caster, scene.lights[light],
                                                job.view, options);  // 3
        finish_step(2, start);
        result.jobs.push_back(std::move(job));
      }
    }
  }
  auto start = Clock::now();
  render_scene(scene, frame);  // 4
  finish_step(3, start);
  start = Clock::now();
  // 5, a light at a time (jobs are in light order). Between lights the depth buffer gets step
  // 4's surfaces back (a depth-only scene pass), so each light's marks start from them.
  std::vector<const ShadowJob *> same_light;
  for (std::size_t j = 0; j < result.jobs.size(); ++j) {
    same_light.push_back(&result.jobs[j]);
    if (j + 1 < result.jobs.size() && result.jobs[j + 1].light == result.jobs[j].light) continue;
    render_light_shadow_passes(same_light, options);
    same_light.clear();
    if (j + 1 < result.jobs.size()) {
      grColorMask(FXFALSE, FXFALSE);
      render_scene(scene, frame);
      grColorMask(FXTRUE, FXFALSE);
    }
  }
  finish_step(4, start);
  result.times.total_ms = elapsed_ms(frame_start);
  result.geometry = std::move(frame);
  // Errors are warnings too, so that a caller showing only warnings still shows them.
  result.warnings.insert(result.warnings.begin(), result.errors.begin(), result.errors.end());
  return result;
}

namespace {

void draw_mask(const ProjectedShadowOptions &options, const ShadowFrame &frame,
               FxI16 exact_codes, FxI16 clipped_codes) {
  grDepthMask(FXFALSE);
  grBufferClear(0, 0, 0);  // colour only: the depth buffer keeps the frame's surfaces
  for (const ShadowJob &job : frame.jobs) {
    set_shadow_pass_state(job.texture, options);
    // White where the pixel is in shadow as technique.h defines it: at least half of the
    // light's view of the point covered by the caster, i.e. the filtered texture alpha at least
    // 128 (the chroma-key variant samples one texel: the key rejects uncovered ones, and every
    // texel left is covered).
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_TEXTURE, FXFALSE);
    grConstantColorValue(0xFFFFFFFFu);
    grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
    if (options.chroma_key) {
      grAlphaTestFunction(GR_CMP_GREATER);
      grAlphaTestReferenceValue(0);
    } else {
      grAlphaCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                     GR_COMBINE_OTHER_TEXTURE, FXFALSE);  // the texture's alpha alone
      grAlphaTestFunction(GR_CMP_GEQUAL);
      grAlphaTestReferenceValue(128);
    }
    grDepthBiasLevel(-exact_codes);
    draw_exact(job.receivers);
    grDepthBiasLevel(-clipped_codes);
    draw_clipped(job.receivers);
    grDepthBiasLevel(0);
  }
  restore_scene_state();
}

}  // namespace

void render_shadow_mask(const ProjectedShadowOptions &options, const ShadowFrame &frame) {
  draw_mask(options, frame, kSealCodes + 8, kSealCodes + 8);
}

void render_shadow_mask(const Scene &scene, const ProjectedShadowOptions &options,
                        const ShadowFrame &frame) {
  grColorMask(FXFALSE, FXFALSE);
  render_scene(scene, frame.geometry);  // step 4's depth, without step 5's marks
  grColorMask(FXTRUE, FXFALSE);
  // LEQUAL at step 4's depth, as step 5 would find the surfaces without marks.
  draw_mask(options, frame, 0, 8);
}

}  // namespace gs
