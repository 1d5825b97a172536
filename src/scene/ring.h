// The fighting ring: a raised platform whose mat has relief, steps up to it, corner posts and
// three ropes a side; at least 2,000 triangles. World space, y up, the mat centred on the origin.
#pragma once

#include "scene/mesh.h"

namespace gs {

struct RingSize {
  float mat_half_width = 3.0f;  // metres from the centre to the ropes
  float platform_height = 1.0f; // mat surface above the floor, before relief
};

Mesh build_ring(const RingSize &size = {});
// Height of the mat's surface (relief included) at (x, z), for standing fighters on it.
float ring_mat_height(float x, float z, const RingSize &size = {});

}  // namespace gs
