// Uploading TMU memory to GL. Every level a chain holds goes into one GL texture (an atlas,
// levels stacked top to bottom) that the shader indexes texel by texel with GL_NEAREST, so GL
// never filters or picks levels itself. ARGB_4444 goes up as it is (3-4 us for 256x256 on
// Mesa 22.3, measured): GL's widening of a 4-bit channel, n/15, is exactly the TMU's bit
// replication (17n). Every other format is widened here to RGBA8, once per upload, so the shader
// only reads exact 8-bit values.
#include "gl/texture_cache.h"

#include "texture_layout.h"

#include <algorithm>
#include <cstring>

namespace glide_shim {
namespace {

// The TMU's widening of a `bits`-wide channel to 8 bits: its bits repeated, top 8 kept.
std::uint8_t replicate(unsigned value, int bits) {
  unsigned out = 0;
  int filled = 0;
  while (filled < 8) {
    out = (out << bits) | value;
    filled += bits;
  }
  return static_cast<std::uint8_t>(out >> (filled - 8));
}

// A 9-bit two's complement field of an NCC I or Q word.
int signed9(FxU32 word, int shift) {
  const int field = static_cast<int>((word >> shift) & 0x1FF);
  return field >= 256 ? field - 512 : field;
}

std::uint8_t clamp255(int value) { return static_cast<std::uint8_t>(std::clamp(value, 0, 255)); }

// The NCC decode of one 8-bit YIQ texel, bits YYYYIIQQ: Y from the table's 16 8-bit entries plus
// the signed 9-bit I and Q vectors, each channel clamped to 0..255 (MAME's ncc_table).
void ncc_rgb(const FxU32 table[12], unsigned texel, std::uint8_t &r, std::uint8_t &g,
             std::uint8_t &b) {
  const unsigned y_index = texel >> 4, i_index = (texel >> 2) & 3, q_index = texel & 3;
  const int y = static_cast<int>((table[y_index / 4] >> (8 * (y_index % 4))) & 0xFF);
  const FxU32 i = table[4 + i_index], q = table[8 + q_index];
  r = clamp255(y + signed9(i, 18) + signed9(q, 18));
  g = clamp255(y + signed9(i, 9) + signed9(q, 9));
  b = clamp255(y + signed9(i, 0) + signed9(q, 0));
}

void palette_rgb(const FxU32 palette[256], unsigned index, std::uint8_t &r, std::uint8_t &g,
                 std::uint8_t &b) {
  const FxU32 entry = palette[index & 0xFF];
  r = static_cast<std::uint8_t>(entry >> 16), g = static_cast<std::uint8_t>(entry >> 8),
  b = static_cast<std::uint8_t>(entry);
}

struct GlUpload {
  GLint internal_format;
  GLenum format, type;
};

constexpr GlUpload kArgb4444 = {GL_RGBA4, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV};  // A in 15-12
constexpr GlUpload kWidened = {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};

constexpr std::int64_t kNotHeld = INT64_MIN;  // a level address the chain does not have

}  // namespace

bool uses_tables(GrTextureFormat_t format) {
  return format == GR_TEXFMT_P_8 || format == GR_TEXFMT_AP_88 || format == GR_TEXFMT_YIQ_422 ||
         format == GR_TEXFMT_AYIQ_8422;
}

void decode_texels(GrTextureFormat_t format, const TextureTables &tables,
                   const std::uint8_t *texels, int count, std::uint8_t *rgba) {
  const FxU32 *ncc = tables.ncc[tables.ncc_select == GR_NCCTABLE_NCC1 ? 1 : 0];
  for (int i = 0; i < count; ++i, rgba += 4) {
    unsigned t = 0;
    if (bytes_per_texel(format) == 1) {
      t = texels[i];
    } else {
      std::uint16_t word;
      std::memcpy(&word, texels + 2 * i, 2);
      t = word;
    }
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
    switch (format) {
      case GR_TEXFMT_RGB_332:
        r = replicate((t >> 5) & 7, 3), g = replicate((t >> 2) & 7, 3), b = replicate(t & 3, 2);
        break;
      case GR_TEXFMT_YIQ_422: ncc_rgb(ncc, t, r, g, b); break;
      case GR_TEXFMT_ALPHA_8: r = g = b = a = static_cast<std::uint8_t>(t); break;
      case GR_TEXFMT_INTENSITY_8: r = g = b = static_cast<std::uint8_t>(t); break;
      case GR_TEXFMT_ALPHA_INTENSITY_44:
        a = replicate(t >> 4, 4), r = g = b = replicate(t & 0xF, 4);
        break;
      case GR_TEXFMT_P_8: palette_rgb(tables.palette, t, r, g, b); break;
      case GR_TEXFMT_ARGB_8332:
        a = static_cast<std::uint8_t>(t >> 8);
        r = replicate((t >> 5) & 7, 3), g = replicate((t >> 2) & 7, 3), b = replicate(t & 3, 2);
        break;
      case GR_TEXFMT_AYIQ_8422:
        a = static_cast<std::uint8_t>(t >> 8);
        ncc_rgb(ncc, t & 0xFF, r, g, b);
        break;
      case GR_TEXFMT_RGB_565:
        r = replicate(t >> 11, 5), g = replicate((t >> 5) & 0x3F, 6), b = replicate(t & 0x1F, 5);
        break;
      case GR_TEXFMT_ARGB_1555:
        a = (t & 0x8000) != 0 ? 255 : 0;
        r = replicate((t >> 10) & 0x1F, 5), g = replicate((t >> 5) & 0x1F, 5),
        b = replicate(t & 0x1F, 5);
        break;
      case GR_TEXFMT_ARGB_4444:
        a = replicate(t >> 12, 4), r = replicate((t >> 8) & 0xF, 4),
        g = replicate((t >> 4) & 0xF, 4), b = replicate(t & 0xF, 4);
        break;
      case GR_TEXFMT_ALPHA_INTENSITY_88:
        a = static_cast<std::uint8_t>(t >> 8), r = g = b = static_cast<std::uint8_t>(t & 0xFF);
        break;
      case GR_TEXFMT_AP_88:
        a = static_cast<std::uint8_t>(t >> 8);
        palette_rgb(tables.palette, t & 0xFF, r, g, b);
        break;
      default: break;
    }
    rgba[0] = r, rgba[1] = g, rgba[2] = b, rgba[3] = a;
  }
}

bool TextureCache::Key::operator==(const Key &o) const {
  if (format != o.format || aspect != o.aspect || large_lod != o.large_lod ||
      small_lod != o.small_lod || even_odd != o.even_odd) {
    return false;
  }
  return std::equal(address, address + kLodCount, o.address);
}

BoundTexture TextureCache::bind(const GlFunctions &gl, const TmuState &tmu) {
  const TextureSource &source = tmu.source;
  // Programs that place textures at many addresses would grow the cache without end: past a
  // bound, textures overwritten since their upload are dropped (a later use re-creates them).
  if (entries_.size() > kMaxEntries) {
    for (auto it = entries_.begin(); it != entries_.end();) {
      if (it->stale) {
        gl.glDeleteTextures(1, &it->name);
        it = entries_.erase(it);
      } else {
        ++it;
      }
    }
  }
  Key key{source.format, source.aspect, source.large_lod, source.small_lod, source.even_odd, {}};
  for (GrLOD_t lod = GR_LOD_256; lod <= GR_LOD_1; ++lod) {
    const bool held = lod >= source.large_lod && lod <= source.small_lod &&
                      level_selected(lod, source.even_odd);
    key.address[lod] = held ? level_address(tmu.base, tmu.multibase, lod, source.aspect,
                                            source.format, source.even_odd)
                            : kNotHeld;
  }
  Entry *entry = nullptr;
  for (Entry &candidate : entries_) {
    if (candidate.key == key) {
      entry = &candidate;
      break;
    }
  }
  const bool created = entry == nullptr;
  if (created) {
    entries_.push_back(Entry{});
    entry = &entries_.back();
    entry->key = key;
    BoundTexture &bound = entry->bound;
    entry->begin = INT64_MAX;
    entry->end = INT64_MIN;
    float row = 0;
    for (GrLOD_t lod = GR_LOD_256; lod <= GR_LOD_1; ++lod) {
      if (key.address[lod] == kNotHeld) continue;
      const LevelSize size = level_size(lod, source.aspect);
      const auto bytes = static_cast<std::int64_t>(size.width * size.height *
                                                   bytes_per_texel(source.format));
      entry->begin = std::min(entry->begin, key.address[lod]);
      entry->end = std::max(entry->end, key.address[lod] + bytes);
      bound.levels[lod][0] = row;
      bound.levels[lod][1] = static_cast<float>(size.width);
      bound.levels[lod][2] = static_cast<float>(size.height);
      bound.levels[lod][3] = 1.0f;
      bound.atlas_width = std::max(bound.atlas_width, static_cast<float>(size.width));
      row += static_cast<float>(size.height);
    }
    bound.atlas_height = std::max(row, 1.0f);
    gl.glGenTextures(1, &entry->name);
  }
  gl.glActiveTexture(GL_TEXTURE0);
  gl.glBindTexture(GL_TEXTURE_2D, entry->name);

  // A restored state (grGlideSetState) can change the NCC choice without a table download.
  if (uses_tables(source.format) && (entry->table_generation != tmu.tables.generation ||
                                     entry->ncc_select != tmu.tables.ncc_select)) {
    entry->stale = true;
  }
  const bool native = source.format == GR_TEXFMT_ARGB_4444;
  const GlUpload upload = native ? kArgb4444 : kWidened;
  if (entry->stale) {
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (created) {
      // Sampling is done texel by texel in the shader, so GL must never filter.
      gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      gl.glTexImage2D(GL_TEXTURE_2D, 0, upload.internal_format,
                      static_cast<GLsizei>(entry->bound.atlas_width),
                      static_cast<GLsizei>(entry->bound.atlas_height), 0, upload.format,
                      upload.type, nullptr);
    }
    for (GrLOD_t lod = GR_LOD_256; lod <= GR_LOD_1; ++lod) {
      if (key.address[lod] == kNotHeld) continue;
      const LevelSize size = level_size(lod, source.aspect);
      const int count = size.width * size.height;
      // Addresses wrap inside TMU memory as the hardware's do (a multibase base can point
      // anywhere); the usual level lies inside it and is read in place.
      const auto bytes = static_cast<std::size_t>(count * bytes_per_texel(source.format));
      const std::int64_t address = key.address[lod];
      const std::uint8_t *raw = nullptr;
      if (address >= 0 && address + static_cast<std::int64_t>(bytes) <= kTmuMemoryBytes) {
        raw = tmu.memory.data() + address;
      } else {
        level_bytes_.resize(bytes);
        for (std::size_t k = 0; k < bytes; ++k) {
          level_bytes_[k] = tmu.memory[static_cast<std::size_t>(
              (static_cast<std::uint64_t>(address) + k) & (kTmuMemoryBytes - 1))];
        }
        raw = level_bytes_.data();
      }
      const void *pixels = raw;
      if (!native) {
        decoded_.resize(static_cast<std::size_t>(count) * 4);
        decode_texels(source.format, tmu.tables, raw, count, decoded_.data());
        pixels = decoded_.data();
      }
      gl.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, static_cast<GLint>(entry->bound.levels[lod][0]),
                         size.width, size.height, upload.format, upload.type, pixels);
    }
    entry->stale = false;
    entry->table_generation = tmu.tables.generation;
    entry->ncc_select = tmu.tables.ncc_select;
  }

  BoundTexture bound = entry->bound;
  bound.lod_min = static_cast<float>(source.large_lod);
  bound.lod_max = static_cast<float>(
      tmu.mipmap_mode == GR_MIPMAP_DISABLE ? source.large_lod : source.small_lod);
  return bound;
}

void TextureCache::invalidate(FxU32 begin, FxU32 end) {
  for (Entry &entry : entries_) {
    if (begin < entry.end && entry.begin < end) entry.stale = true;
  }
}

void TextureCache::release(const GlFunctions &gl) {
  for (Entry &entry : entries_) gl.glDeleteTextures(1, &entry.name);
  entries_.clear();
}

}  // namespace glide_shim
