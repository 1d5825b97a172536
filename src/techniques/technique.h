// One interface for every shadow technique: chosen by name, each renders a whole frame of a
// scene into Glide's back buffer, reports the time of its own steps, and can draw the same kind
// of shadow mask, so the techniques can be compared on equal terms. The mask is white where the
// pixel is in shadow, by one definition for every technique and the ground truth
// (docs/results.md, "What counts as shadow"): some light that shines on the visible point (in
// its beam, the surface facing it) has at least half of its view of the point blocked by a
// caster other than the receiver itself; black elsewhere.
#pragma once

#include "techniques/projected/projected_shadow.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gs {

struct FrameReport {
  std::vector<std::pair<std::string, double>> steps;  // step name, milliseconds
  double total_ms = 0.0;
  // What the user should know (once each), errors among them, so that a caller that only shows
  // warnings still shows every error.
  std::vector<std::string> warnings;
  // Shadows this frame should show and does not (a caster or a light left without its shadow,
  // each naming them): the frame is wrong, and no caller may report it as a success.
  std::vector<std::string> errors;
  // The projected techniques and the depth map: the most screen pixels one shadow texel (or
  // depth-map texel) spans where a shadow edge can fall (texel_footprint.h); 0 for the others.
  double texel_footprint_px = 0.0;
  // The projected techniques: the size each caster's shadow from each light was drawn at
  // (ShadowFrame::sizes, drawn_shadow_size); empty for the others.
  std::vector<DrawnShadowSize> shadow_sizes;
};

class ShadowTechnique {
 public:
  virtual ~ShadowTechnique() = default;
  // The frame into the back buffer. With `synchronous`, each step ends with grSstIdle (or
  // glFinish) so its time includes the rendering it queued.
  virtual FrameReport render(const Scene &scene, bool synchronous) = 0;
  // Right after render and before the next clear: the shadow mask into the back buffer.
  virtual void render_mask(const Scene &scene) = 0;
};

struct TechniqueOptions {
  ProjectedShadowOptions projected;  // projected texture; its `size` is every map's side
  // Depth map: glPolygonOffset factor and units, the slope term's bound and the receiver's own
  // slope, chosen together with the acne sweep (bench/hard_case_sweeps acne,
  // docs/hard_cases_sweeps.md). A receiver's own plane, read across the lookup's texels, is
  // taken off its depth (receiver 0.5: the 2x2 lookup's half-texel reach along each axis;
  // depth_map_lookup.h), so the caster's push needs to cover only what its neighbours read: the
  // floor at the foot of a steep lit wall (the corridor a2 at 512 texels: 0.28% acne at a bound
  // of 2.5 texels, 0.005% at 4, none at 6). The push is bounded to 6 texels' widths at the caster's depth: a share of the depth
  // (0.3) let a box's steep faces pass the floor close behind them (z7, z8: 0.3 to 1.6% false
  // light), and 8 texels with slope 2 let the tube's walls pass the floor in y6 (0.12%).
  float depth_bias_slope = 1.0f;
  float depth_bias_units = 4.0f;     // depth map: glPolygonOffset units
  // Depth map: the slope term and the facet bias move a caster point back along its ray by at
  // most this many texels' world widths at its light-view depth (depth_map_from_light.cpp);
  // infinity: unbounded.
  float depth_bias_bound = 6.0f;
  // Depth map: each receiver triangle compares its depth lowered by this share of its own depth
  // change across one texel along each map axis (depth_map_lookup.h); 0: none.
  float depth_bias_receiver = 0.5f;
  bool depth_map_linear = true;      // depth map: percentage-closer (GL_LINEAR) or nearest
  int depth_map_bits = 24;           // depth map: 16 or 24-bit depth texture
  // Depth map: a caster whose map texels span more screen pixels than this where its shadow
  // edges can lie is left out of the map by name (an error). 0: the measured default for the
  // lookup (depth_map_footprint.h); infinity: no check.
  float depth_map_largest_footprint_px = 0.0f;
  // Depth map: a caster that also receives shadow is drawn into the map with each facet pushed
  // back from the light by how much faster its neighbour falls away within the lookup's reach
  // (depth_map_facets.h): glPolygonOffset's slope term covers a facet's own slope only, and a
  // curved receiver under a low light shadowed itself (acne, up to 0.23% of the pixels). On by
  // default (the acne sweep, docs/hard_cases_sweeps.md); off only to measure that.
  bool depth_map_facet_bias = true;
  enum class VolumeMode { Automatic, ZPass, ZFail } volume_mode = VolumeMode::Automatic;
};

// The names make_technique accepts, in the order --help lists them.
const std::vector<std::string> &technique_names();
// Null, with `error` naming the problem, for an unknown name.
std::unique_ptr<ShadowTechnique> make_technique(const std::string &name,
                                                const TechniqueOptions &options,
                                                std::string &error);

}  // namespace gs
