// A scene's local origin: a world point near its camera, on a 64 m grid, that the passes which
// need millimetres (the depth map's light passes, the truth's Embree rays) subtract from every
// world position before anything is rounded to float. A float holds about 7 digits: a world
// position 3.6 km from the origin is rounded to 0.24 mm, and the light view's translation,
// applied in float, loses as much again, which is hundreds of a 24-bit map's depth units (issue
// 14: 0.2 to 0.6% interior false shadow). Relative to the local origin a scene keeps the
// precision it has near the world's origin wherever it stands.
//
// The grid keeps the move exact: a multiple of 64 subtracted from a float coordinate under 2^29
// m is a multiple of that coordinate's spacing, so the moved scene is the same float geometry,
// not a rounding of it; and a scene whose camera stands within 32 m of the world's origin has
// its local origin there, so it is not moved at all (its frames stay byte-identical).
// Spaces: world (the scene's) and local (world minus the local origin, same axes and metres).
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace gs {

// The spacing of the local origins' grid, metres (a power of two).
constexpr float kLocalOriginGrid = 64.0f;

// World position of `scene`'s local origin: its camera's position rounded to the 64 m grid.
glm::vec3 local_origin(const Scene &scene);

// `scene` itself when its local origin is the world's origin; otherwise `storage`, filled with
// a copy of it in local coordinates (every object's translation, the lights' positions and
// targets, the camera's position and target moved by minus the local origin; directions and
// sizes unchanged).
const Scene &in_local_coordinates(const Scene &scene, Scene &storage);

}  // namespace gs
