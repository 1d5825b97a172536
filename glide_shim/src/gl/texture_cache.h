// GL textures standing for what TMU memory holds. A texture is found by where its levels live
// and how grTexSource reads them; any download overlapping its bytes marks it stale, so a
// re-download to the same address (a shadow texture every frame) is seen by the next draw, and
// a palette or NCC table change re-decodes the textures that read through the tables.
#pragma once

#include "context.h"
#include "gl/gl_functions.h"

#include <cstdint>
#include <vector>

namespace glide_shim {

constexpr int kLodCount = GR_LOD_1 + 1;  // GR_LOD_256 .. GR_LOD_1

// Where the levels of the bound texture sit in its GL texture (an atlas: every level the chain
// holds, largest at the top, stacked downwards at x = 0), and the LOD range sampling clamps to.
struct BoundTexture {
  float atlas_width = 1, atlas_height = 1;  // texels
  // Per GR_LOD value: atlas row of the level's top, width, height (texels), 1 if the chain holds
  // the level (the evenOdd mask can leave it out), else 0.
  float levels[kLodCount][4] = {};
  float lod_min = 0, lod_max = 0;  // GR_LOD values: lodmin and lodmax of the tLOD register
};

// One texel widened to 8 bits per channel as the TMU's look-up does it, for every Glide 2.x
// format: bit replication for the direct formats, the palette for P_8 / AP_88 and the selected
// NCC table for YIQ_422 / AYIQ_8422. Writes `count` RGBA8 texels.
void decode_texels(GrTextureFormat_t format, const TextureTables &tables,
                   const std::uint8_t *texels, int count, std::uint8_t *rgba);
bool uses_tables(GrTextureFormat_t format);  // P_8, AP_88, YIQ_422, AYIQ_8422

class TextureCache {
 public:
  // Binds the texture the TMU's source names to unit 0, uploading it if new or stale.
  BoundTexture bind(const GlFunctions &gl, const TmuState &tmu);
  void invalidate(FxU32 begin, FxU32 end);  // bytes [begin, end) of TMU memory were written
  void release(const GlFunctions &gl);

 private:
  static constexpr std::size_t kMaxEntries = 64;
  struct Key {
    GrTextureFormat_t format;
    GrAspectRatio_t aspect;
    GrLOD_t large_lod, small_lod;
    FxU32 even_odd;
    std::int64_t address[kLodCount];  // of each held level; INT64_MIN where the chain has none
    bool operator==(const Key &o) const;
  };
  struct Entry {
    Key key;
    unsigned name = 0;
    std::int64_t begin = 0, end = 0;  // bytes of TMU memory the levels span
    FxU32 table_generation = 0;       // for formats read through the tables: the tables'
    GrNCCTable_t ncc_select = 0;      // generation and NCC choice the upload decoded with
    bool stale = true;
    BoundTexture bound;
  };
  std::vector<Entry> entries_;
  std::vector<std::uint8_t> level_bytes_;  // one level's raw bytes
  std::vector<std::uint8_t> decoded_;      // scratch for formats GL cannot read directly
};

}  // namespace glide_shim
