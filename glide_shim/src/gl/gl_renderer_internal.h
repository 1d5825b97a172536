// Shared by GlRenderer's source files (gl_renderer.cpp, draw_path.cpp, program_cache.cpp,
// compare_to_bias_draw.cpp): the vertex attribute slots every program binds, and the compiling
// of one shader stage.
#pragma once

#include "gl/gl_functions.h"

#include <string>

namespace glide_shim {
namespace gl_internal {

// The vertex shader's attributes. kPosition holds x, y and the depth, which ShimVertex keeps
// side by side: one attribute fewer for llvmpipe to fetch per vertex.
enum Attribute : unsigned { kPosition = 0, kColor = 1, kStq = 2, kFog = 3 };

// One compiled shader stage, or 0 with `error` set (the compiler's log).
unsigned compile(const GlFunctions &gl, GLenum stage, const std::string &source,
                 std::string &error);

}  // namespace gl_internal
}  // namespace glide_shim
