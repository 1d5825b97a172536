// The emulated frame buffer and the draw path: queued primitives are drawn with one generated
// program per distinct combine/test state, into RGB565 colour buffers that stand for the
// Voodoo's front and back buffers, sharing one depth buffer as the Voodoo's aux buffer does.
#include "gl/gl_renderer.h"

#include "context.h"

#include <algorithm>
#include <cstddef>

namespace glide_shim {
namespace {

enum Attribute : unsigned { kPosition = 0, kDepth = 1, kColor = 2, kStq = 3, kFog = 4 };

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

unsigned compile(const GlFunctions &gl, GLenum stage, const std::string &source,
                 std::string &error) {
  const unsigned shader = gl.glCreateShader(stage);
  const char *text = source.c_str();
  gl.glShaderSource(shader, 1, &text, nullptr);
  gl.glCompileShader(shader);
  GLint ok = GL_FALSE;
  gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    gl.glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    error = std::string("shader compile failed: ") + log;
    gl.glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

GlRenderer::GlRenderer(GlideContext &context, std::unique_ptr<Backend> backend, int width,
                       int height)
    : context_(context), backend_(std::move(backend)), width_(width), height_(height) {}

GlRenderer::~GlRenderer() {
  const GlFunctions &gl = backend_->gl;
  textures_.release(gl);
  for (auto &entry : programs_) gl.glDeleteProgram(entry.second.program);
  if (bias_mark_program_ != 0) gl.glDeleteProgram(bias_mark_program_);
  if (query_ != 0) gl.glDeleteQueries(1, &query_);
  gl.glDeleteFramebuffers(1, &framebuffer_);
  gl.glDeleteRenderbuffers(2, color_buffers_);
  gl.glDeleteRenderbuffers(1, &depth_buffer_);
  if (texture_framebuffer_ != 0) {
    gl.glDeleteFramebuffers(1, &texture_framebuffer_);
    gl.glDeleteRenderbuffers(1, &texture_color_);
    gl.glDeleteRenderbuffers(1, &texture_depth_);
  }
}

std::unique_ptr<GlRenderer> GlRenderer::create(GlideContext &context, BackendKind kind,
                                               int width, int height, std::string &error) {
  std::unique_ptr<Backend> backend = create_backend(kind, width, height, error);
  if (!backend) return nullptr;
  std::unique_ptr<GlRenderer> renderer(
      new GlRenderer(context, std::move(backend), width, height));
  if (!renderer->build_framebuffer(error)) return nullptr;
  return renderer;
}

bool GlRenderer::build_framebuffer(std::string &error) {
  const GlFunctions &gl = backend_->gl;
  gl.glGenFramebuffers(1, &framebuffer_);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glGenRenderbuffers(2, color_buffers_);
  for (int i = 0; i < 2; ++i) {
    gl.glBindRenderbuffer(GL_RENDERBUFFER, color_buffers_[i]);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, width_, height_);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i),
                                 GL_RENDERBUFFER, color_buffers_[i]);
  }
  // 24 bits hold 1/w finely enough for w up to ~1e4 per unit step; stencil is for the shadow
  // volume technique that draws in plain GL between Glide calls.
  gl.glGenRenderbuffers(1, &depth_buffer_);
  gl.glBindRenderbuffer(GL_RENDERBUFFER, depth_buffer_);
  gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width_, height_);
  gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                               depth_buffer_);
  if (gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the RGB565 + depth framebuffer object is incomplete";
    return false;
  }
  target_ = {framebuffer_, width_, height_};
  gl.glViewport(0, 0, width_, height_);
  gl.glDisable(GL_DITHER);  // the shader does the Voodoo's dither itself
  gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.glGenQueries(1, &query_);
  return true;
}

int GlRenderer::buffer_index(GrBuffer_t buffer) const {
  return buffer == GR_BUFFER_FRONTBUFFER ? front_ : 1 - front_;
}

void GlRenderer::swap_buffers() {
  flush();
  front_ = 1 - front_;
}

const ShaderProgram *GlRenderer::program_for(const PipelineKey &key) {
  const std::string name = key.defines();
  auto found = programs_.find(name);
  if (found != programs_.end()) return &found->second;

  const GlFunctions &gl = backend_->gl;
  std::string error;
  const unsigned vs = compile(gl, GL_VERTEX_SHADER, vertex_shader_source(), error);
  unsigned fs = vs ? compile(gl, GL_FRAGMENT_SHADER, fragment_shader_source(key), error) : 0;
  if (vs != 0 && fs == 0 && key.fast) {
    // A context without GLSL 1.30 gets the exact program under the fast key: the same bytes.
    PipelineKey exact = key.without_sources();
    exact.fast = exact.texel_fetch = false;
    fs = compile(gl, GL_FRAGMENT_SHADER, fragment_shader_source(exact), error);
  }
  if (fs == 0) {
    if (vs) gl.glDeleteShader(vs);
    context_.report(GLIDESHIM_ERR_BACKEND, error);
    return nullptr;
  }
  ShaderProgram program;
  program.program = gl.glCreateProgram();
  gl.glAttachShader(program.program, vs);
  gl.glAttachShader(program.program, fs);
  gl.glBindAttribLocation(program.program, kPosition, "a_position");
  gl.glBindAttribLocation(program.program, kDepth, "a_depth");
  gl.glBindAttribLocation(program.program, kColor, "a_color");
  gl.glBindAttribLocation(program.program, kStq, "a_stq");
  gl.glBindAttribLocation(program.program, kFog, "a_fog");
  gl.glLinkProgram(program.program);
  gl.glDeleteShader(vs);
  gl.glDeleteShader(fs);
  GLint linked = GL_FALSE;
  gl.glGetProgramiv(program.program, GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    char log[2048] = {};
    gl.glGetProgramInfoLog(program.program, sizeof log, nullptr, log);
    gl.glDeleteProgram(program.program);
    context_.report(GLIDESHIM_ERR_BACKEND, std::string("shader link failed: ") + log);
    return nullptr;
  }
  auto location = [&](const char *uniform) {
    return gl.glGetUniformLocation(program.program, uniform);
  };
  program.screen = location("u_screen");
  program.y_down = location("u_y_down");
  program.constant = location("u_constant");
  program.chroma = location("u_chroma");
  program.alpha_ref = location("u_alpha_ref");
  program.texture = location("u_texture");
  program.tex_size = location("u_tex_size");
  program.tex_levels = location("u_tex_levels");
  program.lod_range = location("u_lod_range");
  program.lod_bias = location("u_lod_bias");
  program.level = location("u_level");
  program.level_scale = location("u_level_scale");
  program.detail = location("u_detail");
  program.screen_height = location("u_screen_height");
  program.color_select = location("u_color_select");
  program.color_other = location("u_color_other");
  program.alpha_select = location("u_alpha_select");
  program.alpha_other = location("u_alpha_other");
  program.tmu_invert = location("u_tmu_invert");
  program.fog_color = location("u_fog_color");
  program.fog_flags = location("u_fog_flags");
  program.fog_table = location("u_fog_table");
  program.fog_bias = location("u_fog_bias");
  return &programs_.emplace(name, program).first->second;
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
  queue_.insert(queue_.end(), vertices, vertices + count);
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
    // Without mip-mapping the one level sampled: lodmin, or the next if evenOdd left it out.
    int level = static_cast<int>(bound.lod_min);
    if (bound.levels[level][3] < 0.5f) level = std::min(level + 1, kLodCount - 1);
    gl.glUniform4fv(program->level, 1, bound.levels[level]);
    gl.glUniform1f(program->level_scale, 1.0f / static_cast<float>(1 << level));
  } else if (key.texture) {
    // No grTexSource yet: a texture of size 1 reading texel zero of an unbound unit (0,0,0,0).
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    BoundTexture none;
    none.levels[GR_LOD_256][1] = none.levels[GR_LOD_256][2] = none.levels[GR_LOD_256][3] = 1.0f;
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
  if (queue_.empty()) return;
  const GlFunctions &gl = backend_->gl;
  PipelineKey key = pipeline_key(context_, context_.fast_paths);
  if (key.sources && programs_.count(key.defines()) == 0 && ++states_seen_[key.defines()] < 2) {
    key = key.without_sources();  // compiled in once the state is drawn again
  }
  const ShaderProgram *program = program_for(key);
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

std::uint32_t GlRenderer::draw_tested(unsigned mode, int first, int count, bool query,
                                      bool depth_writes) {
  const GlFunctions &gl = backend_->gl;
  if (bias_interval_count_ == 0) {
    if (query) return samples_drawn(mode, first, count);
    gl.glDrawArrays(mode, first, count);
    return 0;
  }
  // COMPARE_TO_BIAS: stencil bit 7 marks the pixels whose stored depth lies in a passing
  // interval (a depth test of a constant fragment depth against the stored one), the primitives
  // draw where it is set, and the bit is cleared again. With depth writes each primitive goes
  // through alone, so the next one's test sees its writes, as on the hardware.
  const unsigned mark = bias_mark_program();
  if (mark == 0) return 0;
  gl.glUseProgram(mark);  // its vertex shader places the vertices as the drawing one does
  gl.glUniform2f(bias_mark_screen_, static_cast<float>(target_.width),
                 static_cast<float>(target_.height));
  gl.glUniform1f(bias_mark_y_down_, context_.raster.origin == GR_ORIGIN_UPPER_LEFT ? 1.0f : 0.0f);
  GLboolean color_mask[4], depth_mask = GL_FALSE;
  gl.glGetBooleanv(GL_COLOR_WRITEMASK, color_mask);
  gl.glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
  // Primitives that cannot overlap (flush_disjoint) need no order among themselves.
  const int step = depth_writes && !disjoint_ ? (primitive_ == Primitive::Triangles ? 3
                                                 : primitive_ == Primitive::Lines  ? 2
                                                                                   : 1)
                                              : count;
  auto stencil_pass = [&](int at, int n, GLenum depth_function, double depth, GLint bit) {
    gl.glDepthFunc(depth_function);
    gl.glUniform1f(bias_mark_depth_, static_cast<float>(depth));
    gl.glStencilFunc(GL_ALWAYS, bit, 0x80);
    gl.glDrawArrays(mode, at, n);
  };
  gl.glEnable(GL_STENCIL_TEST);
  gl.glStencilMask(0x80);
  std::uint32_t passed = 0;
  for (int at = first; at < first + count; at += step) {
    const int n = std::min(step, first + count - at);
    gl.glUseProgram(mark);
    gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.glDepthMask(GL_FALSE);
    gl.glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    stencil_pass(at, n, GL_ALWAYS, 0.0, 0);  // whatever plain GL code left in bit 7
    for (int i = 0; i < bias_interval_count_; ++i) {
      const DepthInterval &interval = bias_intervals_[i];
      if (interval.low <= 0.0) {
        stencil_pass(at, n, GL_GEQUAL, interval.high, 0x80);  // stored <= high
      } else {
        stencil_pass(at, n, GL_LEQUAL, interval.low, 0x80);  // stored >= low
        if (interval.high < 1.0) stencil_pass(at, n, GL_LESS, interval.high, 0);  // not above
      }
    }
    gl.glUseProgram(drawing_program_);
    gl.glColorMask(color_mask[0], color_mask[1], color_mask[2], color_mask[3]);
    gl.glDepthMask(depth_mask);
    gl.glDepthFunc(GL_ALWAYS);
    gl.glStencilFunc(GL_EQUAL, 0x80, 0x80);
    gl.glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    if (query) {
      passed += samples_drawn(mode, at, n);
    } else {
      gl.glDrawArrays(mode, at, n);
    }
    gl.glUseProgram(mark);
    gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.glDepthMask(GL_FALSE);
    gl.glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    stencil_pass(at, n, GL_ALWAYS, 0.0, 0);
  }
  gl.glUseProgram(drawing_program_);
  gl.glColorMask(color_mask[0], color_mask[1], color_mask[2], color_mask[3]);
  gl.glDepthMask(depth_mask);
  gl.glDisable(GL_STENCIL_TEST);
  gl.glStencilMask(0xFF);
  return passed;
}

unsigned GlRenderer::bias_mark_program() {
  if (bias_mark_program_ != 0) return bias_mark_program_;
  const GlFunctions &gl = backend_->gl;
  std::string error;
  const unsigned vs = compile(gl, GL_VERTEX_SHADER, vertex_shader_source(), error);
  const unsigned fs = vs ? compile(gl, GL_FRAGMENT_SHADER, R"(#version 120
uniform float u_depth;  // GL window depth of the interval's end
void main() {
  gl_FragDepth = u_depth;
  gl_FragColor = vec4(0.0);
}
)", error) : 0;
  if (fs == 0) {
    if (vs) gl.glDeleteShader(vs);
    context_.report(GLIDESHIM_ERR_BACKEND, error);
    return 0;
  }
  const unsigned program = gl.glCreateProgram();
  gl.glAttachShader(program, vs);
  gl.glAttachShader(program, fs);
  gl.glBindAttribLocation(program, kPosition, "a_position");
  gl.glLinkProgram(program);
  gl.glDeleteShader(vs);
  gl.glDeleteShader(fs);
  GLint linked = GL_FALSE;
  gl.glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    gl.glDeleteProgram(program);
    context_.report(GLIDESHIM_ERR_BACKEND, "the COMPARE_TO_BIAS stencil program did not link");
    return 0;
  }
  bias_mark_program_ = program;
  bias_mark_depth_ = gl.glGetUniformLocation(program, "u_depth");
  bias_mark_screen_ = gl.glGetUniformLocation(program, "u_screen");
  bias_mark_y_down_ = gl.glGetUniformLocation(program, "u_y_down");
  return program;
}

std::uint32_t GlRenderer::samples_drawn(unsigned mode, int first, int count) {
  const GlFunctions &gl = backend_->gl;
  gl.glBeginQuery(GL_SAMPLES_PASSED, query_);
  gl.glDrawArrays(mode, first, count);
  gl.glEndQuery(GL_SAMPLES_PASSED);
  GLuint passed = 0;
  gl.glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &passed);
  return passed;
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

void GlRenderer::begin_plain_gl() {
  flush();
  stencil_untouched_ = false;  // plain GL code may keep values in the stencil buffer
  const GlFunctions &gl = backend_->gl;
  gl.glPushAttrib(GL_ALL_ATTRIB_BITS);
  gl.glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  for (GLenum matrix : {GL_PROJECTION, GL_MODELVIEW, GL_TEXTURE}) {
    gl.glMatrixMode(matrix);
    gl.glPushMatrix();
    gl.glLoadIdentity();
  }
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glDrawBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + buffer_index(context_.raster.render_buffer)));
  gl.glViewport(0, 0, width_, height_);
  gl.glScissor(0, 0, width_, height_);
  gl.glUseProgram(0);
  gl.glBindTexture(GL_TEXTURE_2D, 0);
  // The shim's generic attribute arrays point into its vertex queue; attribute 0 would override
  // the caller's glVertexPointer. flush() enables them again before the next Glide draw.
  for (unsigned attribute : {kPosition, kDepth, kColor, kStq, kFog}) {
    gl.glDisableVertexAttribArray(attribute);
  }
  for (GLenum cap : {GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_STENCIL_TEST, GL_SCISSOR_TEST}) {
    gl.glDisable(cap);
  }
  gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.glDepthMask(GL_TRUE);
  gl.glStencilMask(0xFF);
  // GL's default clear values: a W-buffer grBufferClear leaves the clear depth at 0 (far 1/w).
  gl.glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl.glClearDepth(1.0);
  gl.glClearStencil(0);
}

void GlRenderer::end_plain_gl() {
  const GlFunctions &gl = backend_->gl;
  for (GLenum matrix : {GL_TEXTURE, GL_MODELVIEW, GL_PROJECTION}) {
    gl.glMatrixMode(matrix);
    gl.glPopMatrix();
  }
  gl.glPopClientAttrib();
  gl.glPopAttrib();
  // State the attribute stack does not cover: the shim sets what it needs before every draw.
  gl.glUseProgram(0);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glActiveTexture(GL_TEXTURE0);
  gl.glBindTexture(GL_TEXTURE_2D, 0);
  gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
  gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
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

void GlRenderer::clear(std::uint16_t rgb565, bool color, double gl_depth, bool depth) {
  flush();
  const GlFunctions &gl = backend_->gl;
  apply_fixed_function_state();
  GLbitfield mask = 0;
  if (color && context_.raster.rgb_mask) {
    // Exact 565 levels, so GL's float-to-565 conversion cannot round them elsewhere.
    gl.glClearColor(static_cast<float>(rgb565 >> 11) / 31.0f,
                    static_cast<float>((rgb565 >> 5) & 0x3F) / 63.0f,
                    static_cast<float>(rgb565 & 0x1F) / 31.0f, 1.0f);
    mask |= GL_COLOR_BUFFER_BIT;
  }
  if (depth) {
    gl.glDepthMask(GL_TRUE);
    gl.glClearDepth(gl_depth);
    mask |= GL_DEPTH_BUFFER_BIT;
    // Fast path: depth and stencil share 32-bit words, and llvmpipe clears depth alone by a
    // read-modify-write of every word (six times the work of the fill that clears both). The
    // shim's own stencil use (COMPARE_TO_BIAS) returns every bit it sets to 0, so until plain GL
    // code has had the frame buffer the stencil holds zeros (or what GL left undefined), and
    // clearing it to 0 as well changes nothing anyone can read.
    const bool texture_target = target_.framebuffer != framebuffer_;
    if (context_.fast_paths && (texture_target || stencil_untouched_)) {
      gl.glStencilMask(0xFF);
      gl.glClearStencil(0);
      mask |= GL_STENCIL_BUFFER_BIT;
    }
  }
  if (mask != 0) gl.glClear(mask);
}

void GlRenderer::read_color(int index, int x, int y, int w, int h, std::uint16_t *dst,
                            std::size_t stride) {
  flush();
  const GlFunctions &gl = backend_->gl;
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glReadBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + index));
  // GL row 0 is the bottom; read the block in one call, then hand rows out top first.
  std::vector<std::uint16_t> block(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  gl.glReadPixels(x, height_ - (y + h), w, h, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, block.data());
  auto *out = reinterpret_cast<std::uint8_t *>(dst);
  for (int row = 0; row < h; ++row) {
    const std::uint16_t *line = block.data() + static_cast<std::size_t>(h - 1 - row) * w;
    std::copy(line, line + w, reinterpret_cast<std::uint16_t *>(out + row * stride));
  }
}

void GlRenderer::write_color(int index, int x, int y, int w, int h, const std::uint16_t *src,
                             std::size_t stride) {
  flush();
  const GlFunctions &gl = backend_->gl;
  std::vector<std::uint16_t> block(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  const auto *in = reinterpret_cast<const std::uint8_t *>(src);
  for (int row = 0; row < h; ++row) {
    const auto *line = reinterpret_cast<const std::uint16_t *>(in + row * stride);
    std::copy(line, line + w, block.data() + static_cast<std::size_t>(h - 1 - row) * w);
  }
  // LFB writes bypass the pixel pipeline: fixed function with every test and blend off.
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glDrawBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + index));
  gl.glUseProgram(0);
  gl.glDisable(GL_SCISSOR_TEST);
  gl.glDisable(GL_DEPTH_TEST);
  gl.glDisable(GL_BLEND);
  gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  gl.glWindowPos2i(x, height_ - (y + h));
  gl.glDrawPixels(w, h, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, block.data());
}

void GlRenderer::write_depth(int x, int y, int w, int h, const float *src) {
  flush();
  const GlFunctions &gl = backend_->gl;
  std::vector<float> block(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (int row = 0; row < h; ++row) {  // rows from the top in, GL rows from the bottom out
    const float *line = src + static_cast<std::size_t>(row) * w;
    std::copy(line, line + w, block.data() + static_cast<std::size_t>(h - 1 - row) * w);
  }
  // GL writes drawn depth only through the depth test, so the test passes always.
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glUseProgram(0);
  gl.glDisable(GL_SCISSOR_TEST);
  gl.glDisable(GL_BLEND);
  gl.glEnable(GL_DEPTH_TEST);
  gl.glDepthFunc(GL_ALWAYS);
  gl.glDepthMask(GL_TRUE);
  gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl.glWindowPos2i(x, height_ - (y + h));
  gl.glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_FLOAT, block.data());
}

void GlRenderer::begin_texture_target(int side) {
  flush();
  const GlFunctions &gl = backend_->gl;
  if (side != texture_side_) {
    if (texture_framebuffer_ == 0) {
      gl.glGenFramebuffers(1, &texture_framebuffer_);
      gl.glGenRenderbuffers(1, &texture_color_);
      gl.glGenRenderbuffers(1, &texture_depth_);
    }
    gl.glBindFramebuffer(GL_FRAMEBUFFER, texture_framebuffer_);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, texture_color_);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, side, side);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                 texture_color_);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, texture_depth_);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, side, side);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                 texture_depth_);
    texture_side_ = side;
  }
  target_ = {texture_framebuffer_, side, side};
}

void GlRenderer::end_texture_target(std::uint16_t *words) {
  flush();
  const GlFunctions &gl = backend_->gl;
  gl.glBindFramebuffer(GL_FRAMEBUFFER, texture_framebuffer_);
  gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
  std::vector<std::uint16_t> block(static_cast<std::size_t>(texture_side_) * texture_side_);
  gl.glReadPixels(0, 0, texture_side_, texture_side_, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, block.data());
  for (int row = 0; row < texture_side_; ++row) {  // GL rows bottom first; texels top first
    const std::uint16_t *line = block.data() + static_cast<std::size_t>(texture_side_ - 1 - row) * texture_side_;
    std::copy(line, line + texture_side_, words + static_cast<std::size_t>(row) * texture_side_);
  }
  target_ = {framebuffer_, width_, height_};
}

void GlRenderer::read_depth(int x, int y, int w, int h, float *dst) {
  flush();
  const GlFunctions &gl = backend_->gl;
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  std::vector<float> block(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  gl.glReadPixels(x, height_ - (y + h), w, h, GL_DEPTH_COMPONENT, GL_FLOAT, block.data());
  for (int row = 0; row < h; ++row) {
    const float *line = block.data() + static_cast<std::size_t>(h - 1 - row) * w;
    std::copy(line, line + w, dst + static_cast<std::size_t>(row) * w);
  }
}

}  // namespace glide_shim
