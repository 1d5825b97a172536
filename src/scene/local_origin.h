// A scene's local origin: a world point near the scene, on a grid as fine as the scene is
// large, that the passes which need the scene's own precision (the depth map's passes, the
// truth's Embree rays) subtract from every world position before anything is rounded to float.
// A float holds about 7 digits: 3.6 km from the origin a world position is rounded to 0.24 mm,
// and the light view's translation, applied in float, loses as much again, hundreds of a 24-bit
// map's depth units (issue 14: 0.2 to 0.6% interior false shadow from the depth map). Relative
// to its local origin a scene keeps the precision it has at the world's origin wherever it
// stands, as renderers draw relative to a local origin (camera-relative rendering).
//
// The grid: the power of two at least twice the widest side of the box around every object's
// world vertices and the camera, so the local coordinates stay within a few times the scene's
// size, and the move changes nothing a scale of the scene would not (the grid scales with it).
// A multiple of it subtracted from a float coordinate at least as far out is exact (a multiple of
// that coordinate's spacing, no larger), so the moved scene's translations, lights and camera
// are the scene's own floats moved, not a rounding of them. A scene whose box holds
// the world's origin has its local origin there (the box's centre is within a quarter of the
// grid), so it is not moved at all and its frames stay byte-identical.
// Spaces: world (the scene's) and local (world minus the local origin, same axes and metres).
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace gs {

// World position of `scene`'s local origin: its box's centre rounded to the grid above; the
// world's origin when the box is empty, a point, or not finite.
glm::vec3 local_origin(const Scene &scene);

// `scene` itself when its local origin is the world's origin; otherwise `storage`, filled with
// a copy of it in local coordinates (every object's translation, the lights' positions and
// targets, the camera's position and target moved by minus the local origin; directions and
// sizes unchanged).
const Scene &in_local_coordinates(const Scene &scene, Scene &storage);

}  // namespace gs
