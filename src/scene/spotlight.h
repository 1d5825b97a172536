// The projective-texture light model of Segal et al. 1992, section 3.2, shared by every renderer
// and by the ground truth: a light's beam is an intensity map of its cross-section (round,
// square, a gobo, a lens's distortion, or an image file), projected from the light over its
// cone; attenuation with distance is a function of the light-space depth, evaluated either per
// vertex or exactly per pixel. Spaces: world; the light's view (the light at the origin looking
// down -z, as glm::lookAt builds it); the beam plane, (u, v) in [-1, 1] across the cone's full
// angle, v up; texel rows from the top of the beam.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gs {

// The light's view and projection: the same matrices for the Glide passes, the GL techniques and
// the ground truth, so every renderer puts the beam in the same place.
glm::mat4 light_view(const SpotLight &light);                 // world -> light view
glm::mat4 light_projection(const SpotLight &light);           // light view -> light clip
constexpr float kLightNearPlane = 0.05f;                      // light view, metres
constexpr float kLightFarPlane = 1000.0f;

// Where `world` falls on the beam plane; false when the point is behind the light's near plane.
bool beam_coordinates(const SpotLight &light, const glm::vec3 &world, glm::vec2 &uv);

bool is_beam_pattern(const std::string &name);  // round, square, gobo, lens
// The beam's intensity 0..1 at (u, v), exact: the analytic pattern, or the image bilinearly
// sampled (its luminance). 0 outside [-1, 1]^2.
float beam_intensity(const SpotLight &light, const glm::vec2 &uv);

// An image's colour at beam-plane (u, v), bilinear between texel centres, clamped at the edges.
glm::vec3 sample_projected_image(const ProjectedImage &image, const glm::vec2 &uv);

// Attenuation with distance, 1 / (constant + linear d + quadratic d^2) clamped to 1, where d is
// the light-space depth (the distance along the beam's axis, the paper's z_t before its
// projective mapping): the same on every point of a plane facing the light.
float distance_attenuation(const SpotLight &light, float axial_distance);
float axial_distance(const SpotLight &light, const glm::vec3 &world);  // light view depth, metres

// The texture sizes both renderings of the light passes use (the Glide passes and the plain-GL
// units of depth maps and stencil volumes), so that they light alike: beam maps are
// kBeamMapSide texels a side (the patterns' edges within a texel), attenuation ramps
// kAttenuationMapWidth texels over [near, farthest].
constexpr int kBeamMapSide = 128;
constexpr int kAttenuationMapWidth = 256;

// The beam map as a texture: side x side intensities 0..255, row 0 at the top of the beam, each
// texel the exact intensity at its centre, and the outer ring of texels black so that clamp mode
// adds no light outside the cone.
std::vector<std::uint8_t> beam_texels(const SpotLight &light, int side);

// The attenuation as a 1-D texture over [near, far] of light-space depth: `width` texels, texel
// i holding the attenuation at near + (i + 0.5) / width * (far - near).
std::vector<std::uint8_t> attenuation_texels(const SpotLight &light, float near_distance,
                                             float far_distance, int width);

}  // namespace gs
