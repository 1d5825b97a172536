// LFB writes through the pixel pipeline. Each written pixel becomes one point at its pixel
// centre, drawn by the triangle path's own generated program with the LFB data as the iterated
// colour, so the chroma key, alpha test, fog, blending, dither, masks, clip window and depth test
// are the very code triangles use. For the draw the context holds the state a pipelined LFB
// write sees on the hardware, the way grLfbLock rewrites fbzMode and zaColor for a lock and
// grLfbUnlock restores them (glfb.c).
#include "lfb_pipeline.h"

#include "depth.h"
#include "gl/gl_renderer.h"

namespace glide_shim {
namespace {

// The state swapped in for one pipelined LFB draw, restored when it goes out of scope.
class PipelineState {
 public:
  PipelineState(GlideContext &context, GrBuffer_t buffer, bool write_color)
      : context_(context), color_path_(context.color_path), depth_(context.depth),
        raster_(context.raster) {
    // The colour combine is bypassed: the written RGBA is both the 'other' colour the chroma key
    // compares and the combined colour, and no texel is read.
    const CombineUnit written{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                              GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, false};
    context.color_path.color = written;
    context.color_path.alpha = written;
    // grLfbLock loads zaColor with the lock's constant depth and clears fbzMode's depth-bias
    // enable: neither the depth test nor the fog table sees grDepthBiasLevel, and the
    // COMPARE_TO_BIAS modes compare the constant depth with the stored one.
    context.depth.bias_level = compares_to_bias(context.depth.mode)
                                   ? static_cast<FxI16>(context.lfb.write_depth)
                                   : FxI16{0};
    // The aux buffer is written per the depth mask even with depth buffering off (MAME's
    // write_pixel); GL writes depth only through its depth test, so that test passes always.
    if (context.depth.mode == GR_DEPTHBUFFER_DISABLE && context.depth.mask) {
      context.depth.mode = GR_DEPTHBUFFER_ZBUFFER;
      context.depth.function = GR_CMP_ALWAYS;
    }
    if (write_color) {
      context.raster.render_buffer = buffer;
    } else {
      context.raster.rgb_mask = false;  // ZA16 carries no colour; it may name the aux buffer
    }
  }
  ~PipelineState() {
    context_.vertex_fields_stale = true;
    context_.color_path = color_path_;
    context_.depth = depth_;
    context_.raster = raster_;
  }
  PipelineState(const PipelineState &) = delete;
  PipelineState &operator=(const PipelineState &) = delete;

 private:
  GlideContext &context_;
  ColorPathState color_path_;
  DepthState depth_;
  RasterState raster_;
};

}  // namespace

void write_through_pipeline(GlideContext &context, GrBuffer_t buffer, bool write_color,
                            const std::vector<LfbPixel> &pixels) {
  if (pixels.empty()) return;
  GlRenderer &renderer = *context.renderer;
  renderer.flush();  // what was drawn before the unlock, with its own state
  const PipelineState lfb_state(context, buffer, write_color);
  const bool w_buffer = is_w_buffer(context.depth.mode);
  const GrFogMode_t fog_source = context.fog.mode & 0xFF;
  const bool upper_left = context.raster.origin == GR_ORIGIN_UPPER_LEFT;
  const int height = context.display.height;
  std::vector<ShimVertex> points(pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const LfbPixel &pixel = pixels[i];
    ShimVertex &v = points[i];
    // The vertex shader takes screen pixels in the render origin; rows here count from the top.
    v.x = static_cast<float>(pixel.x) + 0.5f;
    v.y = upper_left ? static_cast<float>(pixel.row) + 0.5f
                     : static_cast<float>(height - pixel.row) - 0.5f;
    v.depth = static_cast<float>(gl_depth_from_code(pixel.depth, w_buffer));
    v.r = static_cast<float>(pixel.color.r), v.g = static_cast<float>(pixel.color.g);
    v.b = static_cast<float>(pixel.color.b), v.a = static_cast<float>(pixel.color.a);
    // The fog unit reads the written depth code: the table by it as a W code (1/w exact in
    // float, so the shader's w_code gives the code back), iterated Z as its top 8 bits.
    if (fog_source == GR_FOG_WITH_TABLE) v.fog = static_cast<float>(oow_from_w_code(pixel.depth));
    if (fog_source == GR_FOG_WITH_ITERATED_Z) v.fog = static_cast<float>(pixel.depth);
  }
  renderer.queue(Primitive::Points, points.data(), static_cast<int>(points.size()));
  renderer.flush_disjoint();  // no two points share a pixel
}

}  // namespace glide_shim
