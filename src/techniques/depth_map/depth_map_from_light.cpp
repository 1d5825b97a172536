// Depth-map shadows, step 1: each light's frustum fitted to the casters in its beam, and the
// casters' depth rendered from the light into that light's map. Spaces: world (the meshes, the
// light); light view (the light at the origin looking down -z; depths in metres) and light clip
// (GL convention); the map's texels (side x side, depth 0..1 from near to far plane).
#include "techniques/depth_map/depth_map_passes.h"

#include "techniques/depth_map/depth_map_contacts.h"
#include "techniques/depth_map/depth_map_facets.h"
#include "techniques/depth_map/depth_map_footprint.h"
#include "techniques/depth_map/depth_map_hover.h"
#include "techniques/depth_map/depth_map_lowered.h"
#include "techniques/depth_map/depth_map_self_shadow.h"
#include "techniques/depth_map/depth_map_strips.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/texel_error/shadow_edge_error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace gs::depth_map {
namespace {

constexpr float kWidestCone = 179.0f;  // degrees; wider, the square frustum degenerates
// Map sides refused: under 32 texels a map cannot resolve a caster (at 1 the whole cone is one
// sample), and GL's depth textures stop at 4096 here.
constexpr int kSmallestMap = 32, kLargestMap = 4096;

LightFrustum fit_light_frustum(const std::vector<WorldMesh> &meshes, const SpotLight &light,
                               std::size_t index, int side) {
  LightFrustum frustum;
  const std::string name = "light " + std::to_string(index);
  if (!(light.cone_degrees > 0.0f && light.cone_degrees < kWidestCone)) {
    char cone[96];
    std::snprintf(cone, sizeof cone,
                  "a cone of %g degrees has no depth-map frustum (it must be under %g)",
                  static_cast<double>(light.cone_degrees), static_cast<double>(kWidestCone));
    frustum.problem = name + ": " + cone + ", so the light casts no shadow";
    return frustum;
  }
  const glm::vec3 axis = light.target - light.position;
  if (!(glm::length(axis) > 1e-6f)) {
    frustum.problem = name +
                      " has its target at its position: no depth-map frustum, so the "
                      "light casts no shadow";
    return frustum;
  }
  const glm::vec3 up =
      std::abs(glm::normalize(axis).y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  frustum.view = glm::lookAt(light.position, light.target, up);
  float farthest = 0.0f, nearest_caster = INFINITY;  // light-view depth, metres
  for (const WorldMesh &mesh : meshes) {
    for (const glm::vec3 &p : mesh.position) {
      const float depth = -(frustum.view * glm::vec4(p, 1.0f)).z;
      farthest = std::max(farthest, depth);
      if (mesh.object->casts_shadow) nearest_caster = std::min(nearest_caster, depth);
    }
  }
  // A 1000:1 range at the most: 24 bits then still resolve about a millimetre at 10 m. (With
  // no caster the map stays empty and any near plane will do.)
  const float far_plane = std::max(farthest, 1e-3f) * 1.01f;
  const float near_plane = std::clamp(nearest_caster * 0.99f, far_plane * 1e-3f, far_plane * 0.5f);
  // The map holds only what can shadow a point the light shines on: the casters clipped to the
  // beam (light_beam.h), seen along the light's own axis (so q is the light's depth, and the q
  // gate and the beam stay where they are). Their box of directions, plus two texels for the
  // percentage-closer lookup's reach, is usually far narrower than the cone, and every texel
  // finer; a receiver outside it lies on no ray through a caster, and the lit border says so.
  const float t = std::tan(glm::radians(light.cone_degrees) * 0.5f);
  glm::vec2 low(-t), high(t);  // tangents x / -z, y / -z
  const LightBeam beam = light_beam(light);
  glm::vec2 box_low(INFINITY), box_high(-INFINITY);
  for (const WorldMesh &mesh : meshes) {
    if (!mesh.object->casts_shadow) continue;
    bool whole = false;
    for (const glm::vec3 &p : clip_to_beam(mesh.position, mesh.object->mesh.triangles, beam,
                                           far_plane * 1e-4f, whole)) {
      const glm::vec3 v = glm::vec3(frustum.view * glm::vec4(p, 1.0f));
      if (!(-v.z > 0.0f)) continue;
      const glm::vec2 tangent = glm::vec2(v.x, v.y) / -v.z;
      box_low = glm::min(box_low, tangent);
      box_high = glm::max(box_high, tangent);
    }
  }
  if (box_low.x <= box_high.x && box_low.y <= box_high.y) {
    const glm::vec2 width = glm::max(box_high - box_low, glm::vec2(t * 1e-4f));
    const glm::vec2 pad =
        width * (2.0f / std::max(static_cast<float>(side) - 4.0f, 1.0f)) + glm::vec2(t * 1e-6f);
    low = glm::max(box_low - pad, low);
    high = glm::min(box_high + pad, high);
  }
  frustum.projection = glm::frustum(low.x * near_plane, high.x * near_plane, low.y * near_plane,
                                    high.y * near_plane, near_plane, far_plane);
  return frustum;
}

}  // namespace

void Passes::draw_caster(const WorldMesh &mesh, const std::vector<glm::vec3> &positions) {
  gl_.glVertexPointer(3, GL_FLOAT, 0, positions.data());
  gl_.glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.object->mesh.triangles.size() * 3),
                     GL_UNSIGNED_INT, mesh.object->mesh.triangles.data());
}

void Passes::depth_from_lights(std::vector<std::string> &warnings,
                               std::vector<std::string> &errors) {
  gl_.glGenFramebuffers(1, &framebuffer_);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.glDrawBuffer(GL_NONE);
  gl_.glReadBuffer(GL_NONE);
  gl_.glEnable(GL_DEPTH_TEST);
  gl_.glDepthFunc(GL_LESS);
  gl_.glDepthMask(GL_TRUE);
  gl_.glDisable(GL_CULL_FACE);  // a caster shadows from whichever side the light sees it
  // The near plane keeps the map's range at 1000:1 or less, and a caster may pass nearer the
  // light than that (a light inside a box, a millimetre from one face): clipped there, the face
  // would have a hole the light leaks through. Clamped instead, its part nearer than the near
  // plane lands at depth 0 and shadows everything behind it; nothing lies between it and the
  // light. Where no caster crosses the near plane (0.99 of the nearest corner's depth in every
  // other frustum) nothing is clamped, so those maps are unchanged.
  gl_.glEnable(GL_DEPTH_CLAMP);
  // Pushed away from the light by the slope (light-view depth per texel) and a few depth units,
  // so a lit surface compares nearer than its own sample (Everitt et al., "Why is polygon
  // offset needed?").
  gl_.glEnable(GL_POLYGON_OFFSET_FILL);
  gl_.glPolygonOffset(options_.depth_bias_slope, options_.depth_bias_units);
  const GLint filter = options_.depth_map_linear ? GL_LINEAR : GL_NEAREST;
  const float largest_footprint = options_.depth_map_largest_footprint_px > 0.0f
                                      ? options_.depth_map_largest_footprint_px
                                      : kLargestDepthMapFootprintPx;
  // The most pixels the estimated error along the frame's shadow edges may reach
  // (shadow_edge_error.h), from the receivers' pixels once a shadow has an estimate; off with
  // the footprint check. Casters take it in the scene's order, light by light.
  std::optional<float> largest_edge_error;
  if (std::isinf(options_.depth_map_largest_footprint_px)) largest_edge_error = INFINITY;
  float edge_error_taken = 0.0f;  // by the shadows cast so far
  EdgeErrorEstimate edge_error_of_all;  // by every shadow so far, at each doubling of its map
  const EdgeLookup lookup = options_.depth_map_linear ? EdgeLookup::kBilinear : EdgeLookup::kNearest;
  const GLfloat lit_border[4] = {1.0f, 1.0f, 1.0f, 1.0f};  // depth 1: outside the map is lit
  if (options_.depth_map_bits != 16 && options_.depth_map_bits != 24) {
    warnings.push_back("depth-map: " + std::to_string(options_.depth_map_bits) +
                       "-bit depth maps do not exist (16 or 24); using 24");
  }
  // The bound is a number of texels: below 0 (or NaN) the slid copy would come nearer the light
  // than the caster and shadow what it lights, so such a value leaves the slope term unbounded.
  const bool bounded = std::isfinite(options_.depth_bias_bound) && options_.depth_bias_bound >= 0.0f;
  if (!bounded && !std::isinf(options_.depth_bias_bound)) {
    warnings.push_back("depth-map: a slope bound of " + std::to_string(options_.depth_bias_bound) +
                       " is not a number of texels (0 or more); the slope term is unbounded");
  }
  for (std::size_t light = 0; light < scene_.lights.size(); ++light) {
    maps_.push_back(0);
    sides_.push_back(1);
    if (scene_.lights[light].is_projector()) {  // slides cast no shadows: no map, gate open
      frustums_.emplace_back();
      continue;
    }
    const GLsizei side =
        options_.projected.size > 0 ? options_.projected.size : scene_.lights[light].shadow_size;
    sides_.back() = side;
    frustums_.push_back(fit_light_frustum(meshes_, scene_.lights[light], light, side));
    const LightFrustum &frustum = frustums_.back();
    if (side < kSmallestMap || side > kLargestMap) {
      errors.push_back("depth-map: a map of " + std::to_string(side) + " texels for light " +
                       std::to_string(light) + " is outside " + std::to_string(kSmallestMap) +
                       ".." + std::to_string(kLargestMap) + ", so the light casts no shadow");
      warnings.push_back(errors.back());
      maps_.back() = 0;
      continue;
    }
    if (!frustum.problem.empty()) {
      warnings.push_back(frustum.problem);
      errors.push_back(frustum.problem);
      continue;
    }
    // A caster whose shadow edges would stray from the true ones (its texels too coarse for the
    // screen there) is left out of this light's map, by name, as the projected techniques leave
    // out their texture.
    std::vector<bool> drawn(scene_.objects.size(), true);
    // The error beside the lines where casters meet receivers, which no silhouette edge throws
    // (depth_map_contacts.h), joins the error along the shadows' edges.
    const std::vector<ContactError> contacts =
        std::isinf(options_.depth_map_largest_footprint_px)
            ? std::vector<ContactError>(scene_.objects.size())
            : contact_errors(scene_, meshes_, frustum, scene_.lights[light], side, options_);
    // So does the error on receivers seen as thin strips, where an edge nearly along the strip
    // crosses its pixel centres far from where the estimate along the edge puts it
    // (depth_map_strips.h).
    const std::vector<ContactError> strips =
        std::isinf(options_.depth_map_largest_footprint_px)
            ? std::vector<ContactError>(scene_.objects.size())
            : strip_errors(scene_, meshes_, frustum, scene_.lights[light], side, options_);
    // So does the false shadow a caster that receives casts on its own lit side where the light
    // grazes it (depth_map_self_shadow.h): near no edge, a texel's ray strikes it nearer. Each
    // larger size replayed in the frustum fitted at that size (its pad for the lookup's reach
    // is narrower), as the texels' pattern there decides which grazed pixels it shadows.
    std::vector<LightFrustum> frusta;
    for (int size = 0; size < EdgeErrorEstimate::kSizes; ++size) {
      frusta.push_back(size == 0 ? frustum
                                 : fit_light_frustum(meshes_, scene_.lights[light], light, side << size));
    }
    const std::vector<EdgeErrorEstimate> grazed =
        std::isinf(options_.depth_map_largest_footprint_px)
            ? std::vector<EdgeErrorEstimate>(scene_.objects.size())
            : self_shadow_errors(scene_, meshes_, frusta, scene_.lights[light], side, options_);
    std::vector<CasterFootprint> footprints =
        caster_footprints(scene_, meshes_, frustum, scene_.lights[light], side, lookup);
    // So does the error across the shadow edges of casters close over their receivers, within
    // the biases' reach (depth_map_hover.h).
    const std::vector<ContactError> hovering =
        std::isinf(options_.depth_map_largest_footprint_px)
            ? std::vector<ContactError>(scene_.objects.size())
            : hover_errors(scene_, meshes_, footprints, frustum, scene_.lights[light], side, options_);
    // So does the false light inside shadows on receiver triangles the light grazes, whose
    // receiver-plane bias passes a caster close in front of them (depth_map_lowered.h).
    const std::vector<ContactError> lowered =
        std::isinf(options_.depth_map_largest_footprint_px)
            ? std::vector<ContactError>(scene_.objects.size())
            : lowered_errors(scene_, meshes_, frustum, scene_.lights[light], side, options_);
    for (CasterFootprint &footprint : footprints) {
      for (const ContactError *extra :
           {&contacts[footprint.caster], &hovering[footprint.caster], &lowered[footprint.caster]}) {
        if (extra->pixels.pixels[0] > footprint.edge_error.pixels[0]) {
          footprint.edge_error_receiver = extra->receiver;
        }
        footprint.edge_error.add(extra->pixels);
      }
      const ContactError &strip = strips[footprint.caster];
      if (strip.pixels.pixels[0] > footprint.edge_error.pixels[0]) {
        footprint.edge_error_receiver = strip.receiver;
      }
      footprint.edge_error.add(strip.pixels);
      const EdgeErrorEstimate &own = grazed[footprint.caster];
      if (own.pixels[0] > footprint.edge_error.pixels[0]) {
        footprint.edge_error_receiver = footprint.caster;
      }
      footprint.edge_error.add(own);
      const float pixels = footprint.coarsest.pixels_per_texel;
      texel_footprint_px_ = std::max(texel_footprint_px_, pixels);
      // The error along its shadow's edges, against what the frame's shadows before it left.
      EdgeErrorEstimate within_budget = footprint.edge_error;
      for (float &estimate : within_budget.pixels) estimate += edge_error_taken;
      if (!largest_edge_error && footprint.edge_error.pixels[0] > 0.0f) {
        largest_edge_error = kEdgeErrorReceiverShare * receiver_screen_pixels(scene_, project_scene(scene_));
      }
      // A refusal names a larger size only where this shadow's error fits beside that of every
      // shadow before it, cast or refused: they may all be cast at that size.
      EdgeErrorEstimate at_larger_sizes = footprint.edge_error;
      at_larger_sizes.add(edge_error_of_all);
      edge_error_of_all.add(footprint.edge_error);
      const bool too_coarse = pixels > largest_footprint;
      if (too_coarse || (largest_edge_error && within_budget.pixels[0] > *largest_edge_error)) {
        drawn[footprint.caster] = false;
        const AcceptedSize accepted = smallest_accepted_size(
            side, kLargestMap, pixels, largest_footprint, at_larger_sizes, largest_edge_error);
        errors.push_back(
            too_coarse ? texel_footprint_error(scene_, light, footprint.caster,
                                               footprint.coarsest.receiver, pixels,
                                               largest_footprint, side, accepted_size_words(accepted))
                       : shadow_edge_error_message(scene_, light, footprint.caster,
                                                   footprint.edge_error_receiver, edge_error_taken,
                                                   within_budget, *largest_edge_error, side,
                                                   accepted));
        warnings.push_back(errors.back());
        continue;
      }
      edge_error_taken += footprint.edge_error.pixels[0];
    }
    GLuint map = 0;
    gl_.glGenTextures(1, &map);
    gl_.glBindTexture(GL_TEXTURE_2D, map);
    const GLint format =
        options_.depth_map_bits == 16 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24;
    gl_.glTexImage2D(GL_TEXTURE_2D, 0, format, side, side, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                     nullptr);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    gl_.glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, lit_border);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);  // (0, 0, 0, result)
    gl_.glBindTexture(GL_TEXTURE_2D, 0);
    gl_.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map, 0);
    if (gl_.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      const std::string size = std::to_string(side);
      errors.push_back("light " + std::to_string(light) + ": a " + size + "x" + size +
                       " depth texture cannot be rendered to, so the light casts no shadow");
      warnings.push_back(errors.back());
      gl_.glDeleteTextures(1, &map);
      continue;
    }
    maps_.back() = map;
    gl_.glViewport(0, 0, side, side);
    gl_.glClearDepth(1.0);  // the light's far plane (Glide's own clears leave other values)
    gl_.glClear(GL_DEPTH_BUFFER_BIT);
    gl_.glMatrixMode(GL_PROJECTION);
    gl_.glLoadMatrixf(&frustum.projection[0][0]);
    gl_.glMatrixMode(GL_MODELVIEW);
    gl_.glLoadMatrixf(&frustum.view[0][0]);
    // Full meshes, not shadow_mesh: a simplified caster would shadow the surface it cuts into.
    std::vector<glm::vec3> slid;    // world; the bound's copy of a caster, reused
    std::vector<glm::vec3> facets;  // world; a self-shadowing caster pushed back between facets
    for (const WorldMesh &mesh : meshes_) {
      const auto object = static_cast<std::size_t>(mesh.object - scene_.objects.data());
      if (!mesh.object->casts_shadow || !drawn[object]) continue;
      // A caster that shadows itself is drawn pushed back where it turns away from the light
      // between facets (depth_map_facets.h).
      const bool pushed = mesh.object->receives_shadow && options_.depth_map_facet_bias;
      if (pushed) facets = facet_pushed_positions(mesh, frustum, scene_.lights[light].position, side);
      const std::vector<glm::vec3> &positions = pushed ? facets : mesh.position;  // world
      draw_caster(mesh, positions);
      // The slope term and the facet push bounded: the same caster again from its own positions
      // with every point slid back along its own ray (the light is the view's origin, so it
      // covers the same texels) by `bound` texels' widths at its light-view depth, units only.
      // GL_LESS keeps the nearer of the two in each texel, so no point is carried back by more
      // than a few texels: a face the light sees almost edge-on spans much of its depth in one
      // texel, and its slope term alone passed the receiver behind it (y6, k1 with the light
      // moved: 1 to 16% false light; a box on a floor under a 64-texel map, 1.7%). Its own acne
      // the receiver's bias takes (depth_map_lookup.h).
      if (bounded) {
        const glm::vec3 &origin = scene_.lights[light].position;  // world
        const float texel_per_metre = frustum.texel_per_metre(side);
        slid.clear();
        for (const glm::vec3 &p : mesh.position) {
          const float depth = -(frustum.view * glm::vec4(p, 1.0f)).z;  // light view, metres
          const float distance = glm::length(p - origin);
          const float back = options_.depth_bias_bound * texel_per_metre * std::max(depth, 0.0f);
          slid.push_back(distance > 0.0f ? p + (p - origin) * (back / distance) : p);
        }
        gl_.glPolygonOffset(0.0f, options_.depth_bias_units);
        draw_caster(mesh, slid);
        gl_.glPolygonOffset(options_.depth_bias_slope, options_.depth_bias_units);
      }
    }
  }
  gl_.glDisable(GL_POLYGON_OFFSET_FILL);
  gl_.glDisable(GL_DEPTH_CLAMP);
  gl_.glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target_framebuffer_));
}

}  // namespace gs::depth_map
