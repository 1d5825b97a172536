// The generated programs: one per distinct PipelineKey (a fast key without GLSL 1.30 gets the
// exact program's source), compiled from shader_source.h's text, linked with the attribute slots
// of gl_renderer_internal.h and kept, with their uniform locations, under the key's defines.
#include "gl/gl_renderer.h"
#include "gl/gl_renderer_internal.h"

#include "context.h"

namespace glide_shim {
namespace gl_internal {

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

}  // namespace gl_internal

using namespace gl_internal;

const ShaderProgram *GlRenderer::program_for(const PipelineKey &key) {
  return program_for(key, key.defines());
}

const ShaderProgram *GlRenderer::program_for(const PipelineKey &key, const std::string &name) {
  auto found = programs_.find(name);
  if (found != programs_.end()) return &found->second;

  const GlFunctions &gl = backend_->gl;
  std::string error;
  unsigned vs = compile(gl, GL_VERTEX_SHADER, vertex_shader_source(key.fast), error);
  unsigned fs = vs ? compile(gl, GL_FRAGMENT_SHADER, fragment_shader_source(key), error) : 0;
  if (fs == 0 && key.fast) {
    // A context without GLSL 1.30 gets the exact program under the fast key: the same bytes.
    if (vs) gl.glDeleteShader(vs);
    PipelineKey exact = key.without_sources();
    exact.fast = exact.texel_fetch = false;
    vs = compile(gl, GL_VERTEX_SHADER, vertex_shader_source(false), error);
    fs = vs ? compile(gl, GL_FRAGMENT_SHADER, fragment_shader_source(exact), error) : 0;
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

}  // namespace glide_shim
