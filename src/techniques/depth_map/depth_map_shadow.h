// Williams's depth-map shadows as Segal et al. (1992, section 3.3) and Everitt et al. ("Hardware
// Shadow Mapping") do them in fixed-function OpenGL with ARB_shadow: each light's depth into a
// texture, then an ambient pass and, per light, an additive lit pass gated by the shadow
// comparison. Plain GL between glideShimBeginGL and glideShimEndGL, into Glide's back buffer.
#pragma once

#include "techniques/technique.h"

#include <memory>

namespace gs {

// The technique "depth-map": map side options.projected.size (0: each light's shadow_size),
// glPolygonOffset(depth_bias_slope, depth_bias_units) in the light's pass with the slope term's
// push bounded to depth_bias_bound texels' widths, each receiver triangle's depth lowered by
// depth_bias_receiver of its own slope, GL_LINEAR (2x2 percentage-closer) or GL_NEAREST lookups,
// depth_map_bits of depth (16 or 24).
std::unique_ptr<ShadowTechnique> make_depth_map_shadow(const TechniqueOptions &options);

}  // namespace gs
