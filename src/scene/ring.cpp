// The fighting ring in world space (y up, the mat centred on the origin): a raised platform
// whose canvas sags and undulates by a few centimetres, the apron around it, steps on the +x
// side, four corner posts, three ropes a side and a turnbuckle pad where each rope meets a post.
#include "scene/ring.h"

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace gs {
namespace {

constexpr float kApronWidth = 0.5f;  // platform beyond the ropes, metres
constexpr int kMatDivisions = 32;    // 2,048 triangles of canvas, ~19 cm cells for the relief
constexpr float kPostRadius = 0.07f;
constexpr float kPostTopAboveMat = 1.5f;
constexpr float kRopeHeightsAboveMat[3] = {0.45f, 0.85f, 1.25f};  // bottom to top
constexpr float kRopeRadius = 0.022f;
constexpr int kRopeSlices = 10;
constexpr int kStepCount = 4;
constexpr float kStepDepth = 0.3f;
constexpr float kStepHalfWidth = 0.6f;

const glm::vec3 kMatColor(0.62f, 0.72f, 0.8f);
const glm::vec3 kApronColor(0.12f, 0.13f, 0.16f);
const glm::vec3 kSkirtColor(0.07f, 0.07f, 0.09f);
const glm::vec3 kStepColor(0.18f, 0.18f, 0.2f);
const glm::vec3 kPostColor(0.6f, 0.62f, 0.65f);
const glm::vec3 kRopeColors[3] = {
    {0.15f, 0.25f, 0.85f}, {0.92f, 0.92f, 0.92f}, {0.85f, 0.1f, 0.1f}};
const glm::vec3 kRedCorner(0.8f, 0.1f, 0.1f), kBlueCorner(0.1f, 0.2f, 0.8f),
    kNeutralCorner(0.9f, 0.9f, 0.9f);

// The canvas over its padding, metres above the platform (world): it sags by 2 cm towards the
// centre, where the fighters stand, and undulates gently; the relief fades to nothing at the
// ropes so that the mat meets the flat apron without a step.
float relief(float x, float z, float half_width) {
  const float u = x / half_width, v = z / half_width;
  const float fade = (1.0f - u * u) * (1.0f - v * v);
  const float undulation = 0.012f * std::sin(2.7f * x + 0.5f) * std::sin(2.1f * z - 0.3f) +
                           0.008f * std::cos(1.9f * (x - z));
  return fade * (undulation - 0.02f);
}

// A flat rectangle from `corner` spanning `along` x `across`, facing along x across (world).
Mesh make_panel(const glm::vec3 &corner, const glm::vec3 &along, const glm::vec3 &across,
                int along_cells, int across_cells, const glm::vec3 &color) {
  Mesh panel;
  const glm::vec3 normal = glm::normalize(glm::cross(along, across));
  for (int j = 0; j <= across_cells; ++j) {
    for (int i = 0; i <= along_cells; ++i) {
      panel.positions.push_back(
          corner + along * (static_cast<float>(i) / static_cast<float>(along_cells)) +
          across * (static_cast<float>(j) / static_cast<float>(across_cells)));
      panel.normals.push_back(normal);
    }
  }
  panel.set_color(color);
  const auto row_length = static_cast<glm::uint>(along_cells + 1);
  for (int j = 0; j < across_cells; ++j) {
    for (int i = 0; i < along_cells; ++i) {
      const auto a = static_cast<glm::uint>(j) * row_length + static_cast<glm::uint>(i);
      panel.triangles.emplace_back(a, a + 1, a + row_length + 1);
      panel.triangles.emplace_back(a, a + row_length + 1, a + row_length);
    }
  }
  return panel;
}

Mesh colored(Mesh mesh, const glm::vec3 &color) {
  mesh.set_color(color);
  return mesh;
}

}  // namespace

float ring_mat_height(float x, float z, const RingSize &size) {
  const float half_width = size.mat_half_width;
  // Beyond the ropes the surface is the flat apron (and NaN lands here too).
  if (!(std::abs(x) < half_width && std::abs(z) < half_width)) return size.platform_height;
  return size.platform_height + relief(x, z, half_width);
}

Mesh build_ring(const RingSize &size) {
  const float w = size.mat_half_width;  // ropes and posts stand on x, z = +-w
  const float apron = w + kApronWidth;  // the platform's edge
  const float top = size.platform_height;
  Mesh ring;

  // The canvas: its vertices lie exactly on ring_mat_height, so fighters stand on what is drawn.
  ring.append(
      colored(make_heightfield(2.0f * w, kMatDivisions,
                               [size](float x, float z) { return ring_mat_height(x, z, size); }),
              kMatColor));

  // The apron: four strips around the mat at the platform height, facing +y.
  const glm::vec3 across_z(0.0f, 0.0f, apron - w), full_x(2.0f * apron, 0.0f, 0.0f);
  ring.append(make_panel({-apron, top, w}, across_z, full_x, 1, 24, kApronColor));
  ring.append(make_panel({-apron, top, -apron}, across_z, full_x, 1, 24, kApronColor));
  const glm::vec3 mat_z(0.0f, 0.0f, 2.0f * w), across_x(apron - w, 0.0f, 0.0f);
  ring.append(make_panel({w, top, -w}, mat_z, across_x, 24, 1, kApronColor));
  ring.append(make_panel({-apron, top, -w}, mat_z, across_x, 24, 1, kApronColor));

  // The platform's sides, floor to apron, each facing outwards.
  const glm::vec3 rise(0.0f, top, 0.0f);
  ring.append(
      make_panel({-apron, 0.0f, apron}, {2.0f * apron, 0.0f, 0.0f}, rise, 12, 2, kSkirtColor));
  ring.append(
      make_panel({apron, 0.0f, -apron}, {-2.0f * apron, 0.0f, 0.0f}, rise, 12, 2, kSkirtColor));
  ring.append(
      make_panel({apron, 0.0f, apron}, {0.0f, 0.0f, -2.0f * apron}, rise, 12, 2, kSkirtColor));
  ring.append(
      make_panel({-apron, 0.0f, -apron}, {0.0f, 0.0f, 2.0f * apron}, rise, 12, 2, kSkirtColor));

  // Steps against the +x side, tallest first, each a solid block from the floor.
  for (int step = 0; step < kStepCount; ++step) {
    const float step_top = top * static_cast<float>(kStepCount - step) / (kStepCount + 1.0f);
    const glm::vec3 centre(apron + (static_cast<float>(step) + 0.5f) * kStepDepth, 0.5f * step_top,
                           0.0f);
    ring.append(colored(make_box({0.5f * kStepDepth, 0.5f * step_top, kStepHalfWidth}), kStepColor),
                glm::translate(glm::mat4(1.0f), centre));
  }

  // Corner posts from the floor through the platform; a turnbuckle pad at each rope, on the
  // post's inner side and turned 45 degrees to face the centre.
  const Mesh post =
      colored(make_cylinder(kPostRadius, top + kPostTopAboveMat, 16, true), kPostColor);
  for (const float x_side : {-1.0f, 1.0f}) {
    for (const float z_side : {-1.0f, 1.0f}) {
      ring.append(post, glm::translate(glm::mat4(1.0f), {x_side * w, 0.0f, z_side * w}));
      const glm::vec3 pad_color =
          x_side == z_side ? (x_side < 0.0f ? kRedCorner : kBlueCorner) : kNeutralCorner;
      const Mesh pad = colored(make_box({0.06f, 0.1f, 0.06f}), pad_color);
      for (const float rope_height : kRopeHeightsAboveMat) {
        const glm::vec3 centre(x_side * (w - kPostRadius), top + rope_height,
                               z_side * (w - kPostRadius));
        ring.append(pad, glm::rotate(glm::translate(glm::mat4(1.0f), centre),
                                     glm::quarter_pi<float>(), glm::vec3(0.0f, 1.0f, 0.0f)));
      }
    }
  }

  // Ropes from post centre to post centre (their open ends hide inside the posts): the
  // cylinder's +y axis turned onto +x for the z sides and onto +z for the x sides.
  for (int rope = 0; rope < 3; ++rope) {
    const float y = top + kRopeHeightsAboveMat[rope];
    const Mesh cord =
        colored(make_cylinder(kRopeRadius, 2.0f * w, kRopeSlices, false), kRopeColors[rope]);
    for (const float side : {-1.0f, 1.0f}) {
      ring.append(cord, glm::rotate(glm::translate(glm::mat4(1.0f), {-w, y, side * w}),
                                    -glm::half_pi<float>(), glm::vec3(0.0f, 0.0f, 1.0f)));
      ring.append(cord, glm::rotate(glm::translate(glm::mat4(1.0f), {side * w, y, -w}),
                                    glm::half_pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f)));
    }
  }
  return ring;
}

}  // namespace gs
