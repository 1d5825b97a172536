// The draw path: primitives wait in the queue while the state stays the same; flush translates
// the context's state into GL (scissor, masks, depth test and blending, and the program's
// uniforms) and draws the queue, stage by stage when grSstPerfStats is counting.
#include "gl/gl_renderer.h"
#include "gl/gl_renderer_internal.h"

#include "context.h"

#include <algorithm>
#include <cstddef>

namespace glide_shim {
namespace {

GLenum gl_compare(GrCmpFnc_t function, bool inverted) {
  // In W-buffer mode GL stores 1/w, which falls as the Voodoo's depth code rises, so every
  // ordering comparison turns around; equality and the constant functions do not.
  switch (function) {
    case GR_CMP_NEVER: return GL_NEVER;
    case GR_CMP_LESS: return inverted ? GL_GREATER : GL_LESS;
    case GR_CMP_EQUAL: return GL_EQUAL;
    case GR_CMP_LEQUAL: return inverted ? GL_GEQUAL : GL_LEQUAL;
    case GR_CMP_GREATER: return inverted ? GL_LESS : GL_GREATER;
    case GR_CMP_NOTEQUAL: return GL_NOTEQUAL;
    case GR_CMP_GEQUAL: return inverted ? GL_LEQUAL : GL_GEQUAL;
    default: return GL_ALWAYS;
  }
}

GLenum gl_blend_factor(GrAlphaBlendFnc_t factor, bool source) {
  switch (factor) {
    case GR_BLEND_ZERO: return GL_ZERO;
    case GR_BLEND_SRC_ALPHA: return GL_SRC_ALPHA;
    case GR_BLEND_SRC_COLOR: return source ? GL_DST_COLOR : GL_SRC_COLOR;  // value 2
    case GR_BLEND_DST_ALPHA: return GL_DST_ALPHA;  // 565 has no alpha planes: reads as 1
    case GR_BLEND_ONE: return GL_ONE;
    case GR_BLEND_ONE_MINUS_SRC_ALPHA: return GL_ONE_MINUS_SRC_ALPHA;
    case GR_BLEND_ONE_MINUS_SRC_COLOR:  // value 6
      return source ? GL_ONE_MINUS_DST_COLOR : GL_ONE_MINUS_SRC_COLOR;
    case GR_BLEND_ONE_MINUS_DST_ALPHA: return GL_ONE_MINUS_DST_ALPHA;
    default:  // 0xF: ALPHA_SATURATE as a source; PREFOG_COLOR (the colour, no fog yet) as a dest
      return source ? GL_SRC_ALPHA_SATURATE : GL_SRC_COLOR;
  }
}

// Without mip-mapping, the one level sampled: lodmin, or the next if evenOdd left it out.
int sampled_level(const BoundTexture &bound) {
  const int level = static_cast<int>(bound.lod_min);
  return bound.levels[level][3] < 0.5f ? std::min(level + 1, kLodCount - 1) : level;
}

// What a TMU with no grTexSource yet samples: a texture of size 1 reading texel zero of an
// unbound unit (0,0,0,0).
BoundTexture no_texture() {
  BoundTexture none;
  none.levels[GR_LOD_256][1] = none.levels[GR_LOD_256][2] = none.levels[GR_LOD_256][3] = 1.0f;
  return none;
}

}  // namespace

using namespace gl_internal;

void GlRenderer::compile_level(PipelineKey &key) {
  const BoundTexture bound = context_.tmu.source.valid ? textures_.bind(backend_->gl, context_.tmu)
                                                       : no_texture();
  const int level = sampled_level(bound);
  key.level_compiled = true;
  key.level_width = static_cast<int>(bound.levels[level][1]);
  key.level_height = static_cast<int>(bound.levels[level][2]);
  key.level_lod = level;
  key.lod_min = static_cast<int>(bound.lod_min);
}

void GlRenderer::apply_fixed_function_state() {
  const GlFunctions &gl = backend_->gl;
  const RasterState &raster = context_.raster;
  gl.glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer);
  gl.glViewport(0, 0, target_.width, target_.height);
  const int attachment = target_.framebuffer == framebuffer_ ? buffer_index(raster.render_buffer) : 0;
  gl.glDrawBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + attachment));

  // The clip window is in the Glide origin; GL's scissor counts rows from the bottom.
  const ClipRect &clip = raster.clip;
  const int clip_bottom = raster.origin == GR_ORIGIN_UPPER_LEFT
                              ? target_.height - static_cast<int>(clip.max_y)
                              : static_cast<int>(clip.min_y);
  gl.glEnable(GL_SCISSOR_TEST);
  gl.glScissor(static_cast<int>(clip.min_x), clip_bottom,
               static_cast<int>(clip.max_x - clip.min_x), static_cast<int>(clip.max_y - clip.min_y));
  const GLboolean rgb = raster.rgb_mask ? GL_TRUE : GL_FALSE;
  gl.glColorMask(rgb, rgb, rgb, GL_FALSE);

  const DepthState &depth = context_.depth;
  bias_interval_count_ = 0;
  if (depth.mode == GR_DEPTHBUFFER_DISABLE) {
    gl.glDisable(GL_DEPTH_TEST);
  } else if (compares_to_bias(depth.mode)) {
    // bias OP stored: draw_tested marks the pixels whose stored depth passes in the stencil
    // buffer first; the depth test itself passes, so a pixel writes its own (unbiased) depth.
    bias_interval_count_ = bias_compare_intervals(depth, bias_intervals_);
    const bool everywhere = bias_interval_count_ == 1 && bias_intervals_[0].low <= 0.0 &&
                            bias_intervals_[0].high >= 1.0;
    if (everywhere) bias_interval_count_ = 0;
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthFunc(bias_interval_count_ == 0 && !everywhere ? GL_NEVER : GL_ALWAYS);
    gl.glDepthMask(depth.mask ? GL_TRUE : GL_FALSE);
  } else {
    const bool w_buffer = depth.mode == GR_DEPTHBUFFER_WBUFFER;
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthFunc(gl_compare(depth.function, w_buffer));
    gl.glDepthMask(depth.mask ? GL_TRUE : GL_FALSE);
  }

  const BlendState &blend = context_.blend;
  if (blend.rgb_src == GR_BLEND_ONE && blend.rgb_dst == GR_BLEND_ZERO) {
    gl.glDisable(GL_BLEND);
  } else {
    // SST-1 forces the alpha factors to ONE/ZERO; with no alpha planes they change nothing.
    gl.glEnable(GL_BLEND);
    gl.glBlendFunc(gl_blend_factor(blend.rgb_src, true), gl_blend_factor(blend.rgb_dst, false));
  }
}

void GlRenderer::set_fog_uniforms(const ShaderProgram &program) {
  const GlFunctions &gl = backend_->gl;
  const FogState &fog = context_.fog;
  const Rgba8 color = unpack_color(fog.color, context_.display.color_format);
  gl.glUniform3f(program.fog_color, color.r, color.g, color.b);
  gl.glUniform2f(program.fog_flags, (fog.mode & GR_FOG_MULT2) != 0 ? 1.0f : 0.0f,
                 (fog.mode & GR_FOG_ADD2) != 0 ? 1.0f : 0.0f);
  // Each entry with the delta grFogTable loads: (next - this) << 2 kept to 8 bits (the last
  // entry's next is itself), as the hardware's table RAM holds it.
  float table[2 * GR_FOG_TABLE_SIZE];
  for (int i = 0; i < GR_FOG_TABLE_SIZE; ++i) {
    const int next = fog.table[i < GR_FOG_TABLE_SIZE - 1 ? i + 1 : i];
    table[2 * i] = fog.table[i];
    table[2 * i + 1] = static_cast<float>(((next - fog.table[i]) * 4) & 0xFF);
  }
  gl.glUniform2fv(program.fog_table, GR_FOG_TABLE_SIZE, table);
  // The depth-bias enable (fbzMode bit 16): Z and W modes, not the COMPARE_TO_BIAS ones.
  const bool biased =
      context_.depth.mode != GR_DEPTHBUFFER_DISABLE && !compares_to_bias(context_.depth.mode);
  gl.glUniform1f(program.fog_bias, biased ? static_cast<float>(context_.depth.bias_level) : 0.0f);
}

void GlRenderer::queue(Primitive primitive, const ShimVertex *vertices, int count) {
  if (primitive != primitive_) {
    flush();
    primitive_ = primitive;
  }
  queue_.append(vertices, static_cast<std::size_t>(count));
}

// Binds `program` and sets every uniform it reads from the context's state.
void GlRenderer::use_program(const ShaderProgram *program, const PipelineKey &key) {
  const GlFunctions &gl = backend_->gl;
  gl.glUseProgram(program->program);
  drawing_program_ = program->program;
  gl.glUniform2f(program->screen, static_cast<float>(target_.width),
                 static_cast<float>(target_.height));
  gl.glUniform1f(program->y_down, context_.raster.origin == GR_ORIGIN_UPPER_LEFT ? 1.0f : 0.0f);
  gl.glUniform1f(program->screen_height, static_cast<float>(target_.height));
  const Rgba8 constant =
      unpack_color(context_.color_path.constant_color, context_.display.color_format);
  gl.glUniform4f(program->constant, constant.r, constant.g, constant.b, constant.a);
  const Rgba8 key_color = unpack_color(context_.chroma.value, context_.display.color_format);
  gl.glUniform4f(program->chroma, key_color.r, key_color.g, key_color.b, 0.0f);
  gl.glUniform1f(program->alpha_ref, context_.blend.alpha_test_reference);
  const UnitUniforms color = unit_uniforms(context_.color_path.color);
  const UnitUniforms alpha = unit_uniforms(context_.color_path.alpha);
  gl.glUniform4fv(program->color_select, 1, color.select);
  gl.glUniform4fv(program->color_other, 1, color.other);
  gl.glUniform4fv(program->alpha_select, 1, alpha.select);
  gl.glUniform4fv(program->alpha_other, 1, alpha.other);
  const TexCombineUnit &tmu = context_.tmu.combine;
  gl.glUniform2f(program->tmu_invert, tmu.rgb_invert ? 1.0f : 0.0f, tmu.alpha_invert ? 1.0f : 0.0f);
  if (key.texture && context_.tmu.source.valid) {
    const BoundTexture bound = textures_.bind(gl, context_.tmu);
    gl.glUniform1i(program->texture, 0);
    gl.glUniform2f(program->tex_size, bound.atlas_width, bound.atlas_height);
    gl.glUniform4fv(program->tex_levels, kLodCount, &bound.levels[0][0]);
    gl.glUniform2f(program->lod_range, bound.lod_min, bound.lod_max);
    gl.glUniform1f(program->lod_bias, context_.tmu.lod_bias);
    const int level = sampled_level(bound);
    gl.glUniform4fv(program->level, 1, bound.levels[level]);
    gl.glUniform1f(program->level_scale, 1.0f / static_cast<float>(1 << level));
  } else if (key.texture) {
    gl.glBindTexture(GL_TEXTURE_2D, 0);  // no grTexSource yet
    const BoundTexture none = no_texture();
    gl.glUniform2f(program->tex_size, 1.0f, 1.0f);
    gl.glUniform4fv(program->tex_levels, kLodCount, &none.levels[0][0]);
    gl.glUniform2f(program->lod_range, 0.0f, 0.0f);
    gl.glUniform1f(program->lod_bias, 0.0f);
    gl.glUniform4fv(program->level, 1, none.levels[GR_LOD_256]);
    gl.glUniform1f(program->level_scale, 1.0f);
  }
  if (key.texture) {
    const TmuState &tmu_state = context_.tmu;
    gl.glUniform3f(program->detail, static_cast<float>(tmu_state.detail_bias),
                   static_cast<float>(1 << tmu_state.detail_scale),
                   static_cast<float>(tmu_state.detail_max));
  }

  if (key.fog != GR_FOG_DISABLE) set_fog_uniforms(*program);
}

void GlRenderer::flush() {
  context_.vertex_fields_stale = true;  // a state change may follow (see GlideContext)
  if (queue_.empty()) return;
  const GlFunctions &gl = backend_->gl;
  PipelineKey key = pipeline_key(context_, context_.fast_paths);
  key.line_rows = key.fast && key.dither != GR_DITHER_DISABLE && primitive_ == Primitive::Lines;
  if (key.sources && key.texture && !key.mipmap) compile_level(key);
  std::string name = key.defines();  // the program cache's key, made once per flush
  if (key.sources && programs_.count(name) == 0 && ++states_seen_[name] < 2) {
    key = key.without_sources();  // compiled in once the state is drawn again
    name = key.defines();
  }
  const ShaderProgram *program = program_for(key, name);
  if (program == nullptr) {
    queue_.clear();
    return;
  }
  apply_fixed_function_state();
  use_program(program, key);

  const GLsizei stride = sizeof(ShimVertex);
  const char *base = reinterpret_cast<const char *>(queue_.data());
  gl.glVertexAttribPointer(kPosition, 2, GL_FLOAT, GL_FALSE, stride,
                           base + offsetof(ShimVertex, x));
  gl.glVertexAttribPointer(kDepth, 1, GL_FLOAT, GL_FALSE, stride,
                           base + offsetof(ShimVertex, depth));
  gl.glVertexAttribPointer(kColor, 4, GL_FLOAT, GL_FALSE, stride, base + offsetof(ShimVertex, r));
  gl.glVertexAttribPointer(kStq, 3, GL_FLOAT, GL_FALSE, stride,
                           base + offsetof(ShimVertex, sow));
  gl.glVertexAttribPointer(kFog, 1, GL_FLOAT, GL_FALSE, stride, base + offsetof(ShimVertex, fog));
  for (unsigned attribute : {kPosition, kDepth, kColor, kStq, kFog}) {
    gl.glEnableVertexAttribArray(attribute);
  }
  const GLenum mode = primitive_ == Primitive::Triangles ? GL_TRIANGLES
                      : primitive_ == Primitive::Lines   ? GL_LINES
                                                         : GL_POINTS;
  if (context_.perf.counting) {
    draw_counting_stages(program, key, mode);
  } else {
    const std::uint32_t passed =
        draw_tested(mode, 0, static_cast<int>(queue_.size()), counting_, context_.depth.mask);
    if (counting_) pixels_counted_ += passed;
  }
  queue_.clear();
}

void GlRenderer::draw_counting_stages(const ShaderProgram *program, const PipelineKey &key,
                                      unsigned mode) {
  // grSstPerfStats, exactly: each primitive is drawn up to three times with colour and depth
  // writes off, counting the pixels that pass no test, the depth test, and depth plus chroma key
  // (the Voodoo's order), then for real with the alpha test too. One primitive at a time, so a
  // primitive's depth test sees the writes of the ones before it, as on the hardware.
  const GlFunctions &gl = backend_->gl;
  PipelineKey untested = key;
  untested.chroma_key = false;
  untested.alpha_test = GR_CMP_ALWAYS;
  PipelineKey chroma_only = key;
  chroma_only.alpha_test = GR_CMP_ALWAYS;
  const ShaderProgram *untested_program = program_for(untested);
  const ShaderProgram *chroma_program = key.chroma_key ? program_for(chroma_only) : nullptr;
  if (untested_program == nullptr || (key.chroma_key && chroma_program == nullptr)) return;
  const bool depth_test = context_.depth.mode != GR_DEPTHBUFFER_DISABLE;
  const int per_primitive = disjoint_ ? static_cast<int>(queue_.size())
                            : primitive_ == Primitive::Triangles ? 3 : primitive_ == Primitive::Lines ? 2 : 1;
  GrSstPerfStats_t &counts = context_.perf.counts;
  for (int first = 0; first + per_primitive <= static_cast<int>(queue_.size()); first += per_primitive) {
    gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.glDepthMask(GL_FALSE);
    use_program(untested_program, untested);
    gl.glDisable(GL_DEPTH_TEST);
    const int bias_intervals = bias_interval_count_;
    bias_interval_count_ = 0;  // no depth test at all for the pixels in
    const std::uint32_t in = samples_drawn(mode, first, per_primitive);
    bias_interval_count_ = bias_intervals;
    if (depth_test) gl.glEnable(GL_DEPTH_TEST);
    const std::uint32_t depth_passed =
        depth_test ? draw_tested(mode, first, per_primitive, true, false) : in;
    std::uint32_t chroma_passed = depth_passed;
    if (chroma_program != nullptr) {
      use_program(chroma_program, chroma_only);
      chroma_passed = draw_tested(mode, first, per_primitive, true, false);
    }
    apply_fixed_function_state();
    use_program(program, key);
    const std::uint32_t out = draw_tested(mode, first, per_primitive, true, context_.depth.mask);
    counts.pixelsIn += in;
    counts.zFuncFail += in - depth_passed;
    counts.chromaFail += depth_passed - chroma_passed;
    counts.aFuncFail += chroma_passed - out;
    counts.pixelsOut += out;
    if (counting_) pixels_counted_ += out;
  }
}

void GlRenderer::flush_disjoint() {
  disjoint_ = true;
  flush();
  disjoint_ = false;
}

void GlRenderer::start_counting() {
  flush();
  counting_ = true;
  pixels_counted_ = 0;
}

}  // namespace glide_shim
