// The projected shadow texture, step by step. Spaces: world; light view (the light at the
// origin looking down -z); light clip (GL convention); Glide screen (pixels, y down) for both
// the light's size x size view in step 1 and the camera in steps 4-5; Glide texture units
// (s, t in 0..256 across the shadow texture).
#include "techniques/projected_shadow.h"

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

LightView fit_light_view(const Scene &scene, std::size_t caster, std::size_t light_index,
                         const ProjectedShadowOptions &options) {
  const SceneObject &object = scene.objects[caster];
  const SpotLight &light = scene.lights[light_index];
  const Sphere sphere = caster_bounds(object);
  LightView view;
  view.position = light.position;
  view.size = options.auto_size  ? screen_size_texture(scene, sphere)
              : options.size > 0 ? options.size
                                 : light.shadow_size;
  if (view.size < 32 || view.size > 512 || (view.size & (view.size - 1)) != 0) {
    view.problem = "shadow size " + std::to_string(view.size) + " for light " +
                   std::to_string(light_index) + " is not a power of two in 32..512";
    return view;
  }
  view.caster_distance = glm::length(sphere.centre - light.position);
  // The view is fitted so the caster's bounding sphere leaves `border_texels` (plus one for the
  // 1/16-pixel snap and bilinear's reach) clean on every side: the Figure 12/13 bug cannot occur.
  const float usable = 1.0f - 2.0f * static_cast<float>(options.border_texels + 1) /
                                  static_cast<float>(view.size);
  const float sine = sphere.radius / std::max(view.caster_distance, 1e-6f);
  const float half_fov = sine < 1.0f ? std::atan(std::tan(std::asin(sine)) / usable) : INFINITY;
  if (!(half_fov < glm::radians(80.0f))) {
    view.problem = "light " + std::to_string(light_index) + " is too close to '" + object.name +
                   "' (" + std::to_string(view.caster_distance) + " m from a caster of radius " +
                   std::to_string(sphere.radius) +
                   " m): no view keeps a clean border, so it casts no shadow";
    return view;
  }
  const glm::vec3 axis = glm::normalize(sphere.centre - light.position);
  const glm::vec3 up = std::abs(axis.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  view.view = glm::lookAt(light.position, sphere.centre, up);
  view.caster_front = view.caster_distance - sphere.radius;
  const float near_plane = std::max(view.caster_front * 0.5f, 1e-3f);
  view.projection = glm::perspective(2.0f * half_fov, 1.0f, near_plane,
                                     view.caster_distance + sphere.radius * 1.01f);
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
  // The flat render: 565 red 11110b on 0, no depth test, back faces culled.
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
  grCullMode(GR_CULL_POSITIVE);
  grBufferClear(0, 0, 0);
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grConstantColorValue(kShadowRedArgb);
  const glm::mat4 light_clip = view.projection * view.view * object.model_to_world;
  const Mesh &mesh = caster_mesh(object);
  std::vector<GrVertex> screen(mesh.positions.size());
  std::vector<float> depth(mesh.positions.size());  // light-view distance along the axis (w)
  for (std::size_t i = 0; i < screen.size(); ++i) {
    const glm::vec4 clip = light_clip * glm::vec4(mesh.positions[i], 1.0f);
    screen[i] = to_screen(clip, view.size, view.size);
    depth[i] = clip.w;
  }
  const float cell = static_cast<float>(view.size) / LightView::kCells;  // texels
  auto cell_index = [&](float texels) {
    return std::clamp(static_cast<int>(std::floor(texels / cell)), 0, LightView::kCells - 1);
  };
  for (const glm::uvec3 &t : mesh.triangles) {
    guDrawTriangleWithClip(&screen[t.x], &screen[t.y], &screen[t.z]);  // tiles cut the caster
    const float x0 = std::min({screen[t.x].x, screen[t.y].x, screen[t.z].x});
    const float x1 = std::max({screen[t.x].x, screen[t.y].x, screen[t.z].x});
    const float y0 = std::min({screen[t.x].y, screen[t.y].y, screen[t.z].y});
    const float y1 = std::max({screen[t.x].y, screen[t.y].y, screen[t.z].y});
    const float nearest = std::min({depth[t.x], depth[t.y], depth[t.z]});
    for (int cy = cell_index(y0); cy <= cell_index(y1); ++cy) {
      for (int cx = cell_index(x0); cx <= cell_index(x1); ++cx) {
        const auto cell_at = static_cast<std::size_t>(cy * LightView::kCells + cx);
        view.occupied[cell_at] = true;
        view.nearest[cell_at] = std::min(view.nearest[cell_at], nearest);
      }
    }
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
    }
    for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
      const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
      // Listing 2: skip triangles facing away from the light and those wholly outside its view.
      if (glm::dot(glm::cross(b - a, c - a), light.position - a) <= 0.0f) continue;
      if ((flags[t.x] & flags[t.y] & flags[t.z]) != 0) continue;
      const unsigned any_outside = flags[t.x] | flags[t.y] | flags[t.z];
      const bool in_front = (any_outside & 0x10) != 0;
      const bool needs_clip = in_front || (view.clip_to_view && (any_outside & 0xF) != 0);
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
      std::vector<glm::vec4> corners;
      for (const ClipVertex &v : polygon) corners.push_back(view.projection * v.clip);
      if (!sees_caster(view, corners.data(), corners.size())) continue;
      std::vector<GrVertex> screen;
      project_camera_polygon(frame, scene, polygon, scratch, screen);
      for (std::size_t i = 0; i < screen.size(); ++i) {
        set_texture_fields(screen[i], view, light, polygon[i].world, options);
      }
      if (screen.size() >= 3) coords.clipped.push_back(std::move(screen));
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

void draw_receivers(const ReceiverCoords &receivers) {
  for (const ShadowTriangle &t : receivers.triangles) {
    guDrawTriangleWithClip(&t.v[0], &t.v[1], &t.v[2]);
  }
  // Clipped polygons are coplanar with what step 4 drew but not made of the same vertices, so
  // they are pulled a few depth codes nearer to pass LEQUAL.
  grDepthBiasLevel(-8);
  for (const std::vector<GrVertex> &polygon : receivers.clipped) draw_fan(polygon);
  grDepthBiasLevel(0);
}

void restore_scene_state() {
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  grAlphaTestFunction(GR_CMP_ALWAYS);
  set_scene_state();
}

}  // namespace

void render_shadow_pass(const ShadowJob &job, const ProjectedShadowOptions &options) {
  set_shadow_pass_state(job.texture, options);
  // Black, at texture alpha x iterated alpha, over the lit scene.
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ZERO,
                 GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                       GR_BLEND_ZERO);
  draw_receivers(job.receivers);
  restore_scene_state();
}

ShadowFrame render_projected_shadows(const Scene &scene, const ProjectedShadowOptions &options,
                                     bool synchronous) {
  ShadowFrame result;
  const auto frame_start = Clock::now();
  auto finish_step = [&](int step, Clock::time_point start) {
    if (synchronous) grSstIdle();
    result.times.ms[step] += elapsed_ms(start);
  };
  const FrameGeometry frame = project_scene(scene);
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
        result.warnings.push_back(fitted.problem);
        continue;
      }
      for (LightView &part : split_into_textures(fitted)) {
        // Each texture takes its own TMU memory; when 2 MB run out, the rest cast nothing.
        GrTexInfo needed{lod_for(part.size), lod_for(part.size), GR_ASPECT_1x1,
                         GR_TEXFMT_ARGB_4444, nullptr};
        if (next_address + grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &needed) >
            grTexMaxAddress(GR_TMU0) + 8) {
          result.warnings.push_back("TMU memory is full: '" + scene.objects[caster].name +
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
          result.warnings.push_back(job.view.problem);
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
  for (const ShadowJob &job : result.jobs) render_shadow_pass(job, options);  // 5
  finish_step(4, start);
  result.times.total_ms = elapsed_ms(frame_start);
  return result;
}

void render_shadow_mask(const ProjectedShadowOptions &options, const ShadowFrame &frame) {
  grDepthMask(FXFALSE);
  grBufferClear(0, 0, 0);  // colour only: the depth buffer keeps the frame's surfaces
  for (const ShadowJob &job : frame.jobs) {
    set_shadow_pass_state(job.texture, options);
    // White wherever step 5 blended a non-zero alpha.
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_TEXTURE, FXFALSE);
    grConstantColorValue(0xFFFFFFFFu);
    grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
    grAlphaTestFunction(GR_CMP_GREATER);
    grAlphaTestReferenceValue(0);
    draw_receivers(job.receivers);
  }
  restore_scene_state();
}

}  // namespace gs
