// One interface for every shadow technique: chosen by name, each renders a whole frame of a
// scene into Glide's back buffer, reports the time of its own steps, and can draw the same kind
// of shadow mask (white where it took a light away from a visible pixel, black elsewhere), so the
// techniques can be compared on equal terms.
#pragma once

#include "techniques/projected_shadow.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gs {

struct FrameReport {
  std::vector<std::pair<std::string, double>> steps;  // step name, milliseconds
  double total_ms = 0.0;
  std::vector<std::string> warnings;                  // what the user should know (once each)
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
  float depth_bias_slope = 1.0f;     // depth map: glPolygonOffset factor
  float depth_bias_units = 4.0f;     // depth map: glPolygonOffset units
  bool depth_map_linear = true;      // depth map: percentage-closer (GL_LINEAR) or nearest
  int depth_map_bits = 24;           // depth map: 16 or 24-bit depth texture
  enum class VolumeMode { Automatic, ZPass, ZFail } volume_mode = VolumeMode::Automatic;
};

// The names make_technique accepts, in the order --help lists them.
const std::vector<std::string> &technique_names();
// Null, with `error` naming the problem, for an unknown name.
std::unique_ptr<ShadowTechnique> make_technique(const std::string &name,
                                                const TechniqueOptions &options,
                                                std::string &error);

}  // namespace gs
