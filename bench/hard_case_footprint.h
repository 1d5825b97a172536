// hard_case_sweeps' footprint sweeps (hard_case_footprint.cpp): each prints a markdown table of
// texel footprint in screen pixels against interior error % for every map size, on the fight's
// frames at 640x480, the sample scenes and the hard cases' footprint classes. False when a
// configuration could not render.
#pragma once

namespace hard_cases {

bool footprint();        // the projected techniques, bilinear and chroma key
bool depth_footprint();  // the depth map, percentage-closer and nearest

}  // namespace hard_cases
