// Uploading TMU memory to GL. ARGB_4444 goes up as it is (3-4 us for 256x256 on Mesa 22.3, measured):
// GL's widening of a 4-bit channel, n/15, is exactly the TMU's bit replication (17n). Every other
// format is widened here by bit replication to RGBA8, once per upload, so the shader only reads
// exact 8-bit values.
#include "texture_cache.h"

#include "texture_layout.h"

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

void decode_to_rgba8(GrTextureFormat_t format, const std::uint8_t *texels, int count,
                     std::uint8_t *rgba) {
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
      case GR_TEXFMT_ALPHA_8: r = g = b = a = static_cast<std::uint8_t>(t); break;
      case GR_TEXFMT_INTENSITY_8: r = g = b = static_cast<std::uint8_t>(t); break;
      case GR_TEXFMT_ALPHA_INTENSITY_44:
        a = replicate(t >> 4, 4), r = g = b = replicate(t & 0xF, 4);
        break;
      case GR_TEXFMT_ARGB_8332:
        a = static_cast<std::uint8_t>(t >> 8);
        r = replicate((t >> 5) & 7, 3), g = replicate((t >> 2) & 7, 3), b = replicate(t & 3, 2);
        break;
      case GR_TEXFMT_RGB_565:
        r = replicate(t >> 11, 5), g = replicate((t >> 5) & 0x3F, 6), b = replicate(t & 0x1F, 5);
        break;
      case GR_TEXFMT_ARGB_1555:
        a = (t & 0x8000) != 0 ? 255 : 0;
        r = replicate((t >> 10) & 0x1F, 5), g = replicate((t >> 5) & 0x1F, 5),
        b = replicate(t & 0x1F, 5);
        break;
      case GR_TEXFMT_ALPHA_INTENSITY_88:
        a = static_cast<std::uint8_t>(t >> 8), r = g = b = static_cast<std::uint8_t>(t & 0xFF);
        break;
      default: break;
    }
    rgba[0] = r, rgba[1] = g, rgba[2] = b, rgba[3] = a;
  }
}

struct GlUpload {
  GLint internal_format;
  GLenum format, type;
};

constexpr GlUpload kArgb4444 = {GL_RGBA4, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV};  // A in 15-12
constexpr GlUpload kWidened = {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};

}  // namespace

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
  const LevelSize size = level_size(source.large_lod, source.aspect);
  Entry *entry = nullptr;
  for (Entry &candidate : entries_) {
    const TextureSource &s = candidate.source;
    if (s.address == source.address && s.format == source.format &&
        s.large_lod == source.large_lod && s.aspect == source.aspect) {
      entry = &candidate;
      break;
    }
  }
  const bool created = entry == nullptr;
  if (created) {
    entries_.push_back(Entry{});
    entry = &entries_.back();
    entry->source = source;
    entry->begin = source.address;
    entry->end = source.address + static_cast<FxU32>(size.width * size.height *
                                                     bytes_per_texel(source.format));
    gl.glGenTextures(1, &entry->name);
  }
  gl.glActiveTexture(GL_TEXTURE0);
  gl.glBindTexture(GL_TEXTURE_2D, entry->name);

  const bool native = source.format == GR_TEXFMT_ARGB_4444;
  const GlUpload upload = native ? kArgb4444 : kWidened;
  if (entry->stale) {
    const std::uint8_t *texels = tmu.memory.data() + source.address;
    const void *pixels = texels;
    if (!native) {
      decoded_.resize(static_cast<std::size_t>(size.width * size.height) * 4);
      decode_to_rgba8(source.format, texels, size.width * size.height, decoded_.data());
      pixels = decoded_.data();
    }
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (created) {
      // Sampling is done texel by texel in the shader, so GL must never filter.
      gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      gl.glTexImage2D(GL_TEXTURE_2D, 0, upload.internal_format, size.width, size.height, 0,
                      upload.format, upload.type, pixels);
    } else {
      gl.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size.width, size.height, upload.format,
                         upload.type, pixels);
    }
    entry->stale = false;
  }

  BoundTexture bound;
  bound.width = static_cast<float>(size.width);
  bound.height = static_cast<float>(size.height);
  bound.scale = static_cast<float>(size.width > size.height ? size.width : size.height) / 256.0f;
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
