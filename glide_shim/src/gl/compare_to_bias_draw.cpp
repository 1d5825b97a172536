// Draws under the COMPARE_TO_BIAS depth modes, which compare the depth bias with the stored
// depth (a test GL's depth test cannot make): stencil bit 7 marks the pixels whose stored depth
// passes, the primitives draw only there, and the bit is cleared again. Also the occlusion query
// that counts the pixels a draw writes.
#include "gl/gl_renderer.h"
#include "gl/gl_renderer_internal.h"

#include "context.h"

#include <algorithm>

namespace glide_shim {

using namespace gl_internal;

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
  const unsigned vs = compile(gl, GL_VERTEX_SHADER, vertex_shader_source(false), error);
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

}  // namespace glide_shim
