// Shared by GlRenderer's source files (gl_renderer.cpp, draw_path.cpp, program_cache.cpp,
// compare_to_bias_draw.cpp): the vertex attribute slots every program binds, and the compiling
// of one shader stage.
#pragma once

#include "gl/gl_functions.h"

#include <string>

namespace glide_shim {
namespace gl_internal {

enum Attribute : unsigned { kPosition = 0, kDepth = 1, kColor = 2, kStq = 3, kFog = 4 };

// One compiled shader stage, or 0 with `error` set (the compiler's log).
unsigned compile(const GlFunctions &gl, GLenum stage, const std::string &source,
                 std::string &error);

}  // namespace gl_internal
}  // namespace glide_shim
