// GL textures standing for what TMU memory holds. A texture is found by where it lives and how
// grTexSource reads it; any download overlapping its bytes marks it stale, so a re-download to
// the same address (a shadow texture every frame) is seen by the next draw.
#pragma once

#include "context.h"
#include "gl_functions.h"

#include <vector>

namespace glide_shim {

struct BoundTexture {
  float width = 1, height = 1;  // largest level, texels
  float scale = 1;              // texels per Glide s,t unit: longer side / 256
};

class TextureCache {
 public:
  // Binds the texture `source` names to unit 0, uploading it if new or stale.
  BoundTexture bind(const GlFunctions &gl, const TmuState &tmu);
  void invalidate(FxU32 begin, FxU32 end);  // bytes [begin, end) of TMU memory were written
  void release(const GlFunctions &gl);

 private:
  static constexpr std::size_t kMaxEntries = 64;
  struct Entry {
    TextureSource source;
    unsigned name = 0;
    FxU32 begin = 0, end = 0;
    bool stale = true;
  };
  std::vector<Entry> entries_;
  std::vector<std::uint8_t> decoded_;  // scratch for formats GL cannot read directly
};

}  // namespace glide_shim
