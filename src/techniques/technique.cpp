// The technique registry, and the two techniques that need no file of their own: none (the
// scene pass alone) and the projected shadow texture (projected_shadow.h) in its two variants.
#include "techniques/technique.h"

#include "techniques/depth_map/depth_map_shadow.h"
#include "techniques/planar/planar_shadow.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/stencil_volume/stencil_volume_shadow.h"

#include <glide.h>
#include <glide_shim.h>

#include <chrono>

namespace gs {
namespace {

class NoShadows final : public ShadowTechnique {
 public:
  FrameReport render(const Scene &scene, bool synchronous) override {
    const auto start = std::chrono::steady_clock::now();
    render_scene(scene, project_scene(scene));
    if (synchronous) grSstIdle();
    FrameReport report;
    report.total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    report.steps.emplace_back("render the scene", report.total_ms);
    return report;
  }
  void render_mask(const Scene &) override {
    grDepthMask(FXFALSE);
    grBufferClear(0, 0, 0);  // nothing is ever darkened
  }
};

class ProjectedTexture final : public ShadowTechnique {
 public:
  explicit ProjectedTexture(const ProjectedShadowOptions &options) : options_(options) {}
  FrameReport render(const Scene &scene, bool synchronous) override {
    frame_ = render_projected_shadows(scene, options_, synchronous);
    static const char *kSteps[5] = {"1 render the caster from the light",
                                    "2 make the texture (LFB read + download)",
                                    "3 (s,t) for the receivers", "4 render the scene",
                                    "5 shadow pass over the flagged triangles"};
    FrameReport report;
    for (int step = 0; step < 5; ++step) report.steps.emplace_back(kSteps[step], frame_.times.ms[step]);
    report.total_ms = frame_.times.total_ms;
    report.warnings = frame_.warnings;
    report.errors = frame_.errors;
    report.texel_footprint_px = frame_.texel_footprint_px;
    report.shadow_sizes = frame_.sizes;
    return report;
  }
  void render_mask(const Scene &scene) override { render_shadow_mask(scene, options_, frame_); }

 private:
  ProjectedShadowOptions options_;
  ShadowFrame frame_;
};

}  // namespace

const std::vector<std::string> &technique_names() {
  static const std::vector<std::string> names = {"projected", "projected-chroma", "planar", "depth-map",
                                                  "stencil-volume", "none"};
  return names;
}

std::unique_ptr<ShadowTechnique> make_technique(const std::string &name,
                                                const TechniqueOptions &options,
                                                std::string &error) {
  if (name == "none") return std::make_unique<NoShadows>();
  if (name == "projected" || name == "projected-chroma") {
    ProjectedShadowOptions projected = options.projected;
    projected.chroma_key = name == "projected-chroma";
    return std::make_unique<ProjectedTexture>(projected);
  }
  if (name == "planar") return make_planar_shadow(options);
  if (name == "stencil-volume") return make_stencil_volume_shadow(options);
  if (name == "depth-map") return make_depth_map_shadow(options);
  error = "unknown technique '" + name + "'";
  return nullptr;
}

}  // namespace gs
