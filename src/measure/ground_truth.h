// The exact answer a shadow technique is measured against: for every pixel centre, a ray from
// the camera finds the visible surface (Embree's BVH, single precision, hit points refined in
// double), and a ray from that point to each light says whether the light reaches it (lit),
// something blocks it (blocked), or it is outside the light's cone or facing away (outside).
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gs {

enum class LightReach : std::uint8_t { Outside = 0, Lit = 1, Blocked = 2 };

struct GroundTruth {
  int width = 0, height = 0;
  std::vector<int> object;                 // per pixel: visible object index, -1 for background
  std::vector<LightReach> reach;           // per pixel and light: reach[pixel * lights + light]
  std::size_t lights = 0;
  // Per pixel: some light in whose cone the surface faces is blocked by another object
  // (what every technique's mask means), and blocked only by the surface's own object.
  std::vector<std::uint8_t> shadow;        // 0 or 1
  std::vector<std::uint8_t> self_shadow;   // 0 or 1
  std::vector<std::uint8_t> rgb;           // the lighting model with exact visibility, 8-bit
};

// False, with `error` naming the problem, if the scene cannot be ray cast (no Embree device,
// an absurd size). Deterministic: the same scene gives the same bytes.
bool compute_ground_truth(const Scene &scene, GroundTruth &truth, std::string &error);

}  // namespace gs
