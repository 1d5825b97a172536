// .3df texture files (gu3dfGetInfo, gu3dfLoad), the format 3dfx's texture tools wrote: four text
// lines ("3df v1.1", the format name, "lod range: <smallest> <largest>" in texels, "aspect
// ratio: <w> <h>"), then for YIQ formats the NCC table (16 Y, 12 I and 12 Q values as big-endian
// 16-bit words), for palette formats 256 big-endian 32-bit palette entries, then every level,
// largest first, row-major, 16-bit texels big-endian. The driver's g3df.c trusts the file; here
// every part is checked, nothing in the caller's Gu3dfInfo changes unless the whole file is good,
// and a bad file is reported as GLIDESHIM_ERR_FILE naming what is wrong.
#include "context.h"
#include "texture_layout.h"

#include <glideutl.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

using glide_shim::current;

namespace {

struct FormatName {
  const char *name;
  GrTextureFormat_t format;
};

// The names texus and g3df.c use, matched without regard to case.
constexpr FormatName kFormatNames[] = {
    {"I8", GR_TEXFMT_INTENSITY_8},     {"A8", GR_TEXFMT_ALPHA_8},
    {"AI44", GR_TEXFMT_ALPHA_INTENSITY_44}, {"YIQ", GR_TEXFMT_YIQ_422},
    {"RGB332", GR_TEXFMT_RGB_332},     {"RGB565", GR_TEXFMT_RGB_565},
    {"ARGB8332", GR_TEXFMT_ARGB_8332}, {"ARGB1555", GR_TEXFMT_ARGB_1555},
    {"AYIQ8422", GR_TEXFMT_AYIQ_8422}, {"ARGB4444", GR_TEXFMT_ARGB_4444},
    {"AI88", GR_TEXFMT_ALPHA_INTENSITY_88}, {"P8", GR_TEXFMT_P_8},
    {"AP88", GR_TEXFMT_AP_88},
};

// A whole file in memory and the position after its header; parse errors say what is wrong.
struct ParsedFile {
  Gu3dfHeader header{};
  std::vector<unsigned char> bytes;
  std::size_t body = 0;  // offset of the first byte after the four header lines
  FxU32 texel_bytes = 0;  // levels as GrTexInfo.data holds them (host sizes, no TMU padding)
};

// GR_LOD value of a side length in texels (1..256, a power of two), or -1.
int lod_of_side(long side) {
  for (int lod = GR_LOD_256; lod <= GR_LOD_1; ++lod) {
    if (side == (256 >> lod)) return lod;
  }
  return -1;
}

// Aspect from "aspect ratio: w h": one side 1, the other 1, 2, 4 or 8.
int aspect_of(long w, long h) {
  for (int k = 0; k <= 3; ++k) {
    if (h == 1 && w == (1L << k)) return GR_ASPECT_1x1 - k;  // wider: 8x1 = 0 .. 1x1 = 3
    if (w == 1 && h == (1L << k)) return GR_ASPECT_1x1 + k;  // taller: 1x2 = 4 .. 1x8 = 6
  }
  return -1;
}

std::string upper(std::string text) {
  for (char &c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

std::string trimmed(const std::string &text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// Reads and checks the header; on failure returns false with `problem` set.
bool parse(const char *filename, ParsedFile &file, std::string &problem) {
  std::ifstream in(filename, std::ios::binary);
  if (!in) {
    problem = "cannot open the file";
    return false;
  }
  file.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  // The header is four short lines; a file without them within 256 bytes is not a .3df file.
  std::string lines[4];
  std::size_t at = 0;
  for (std::string &line : lines) {
    const std::size_t limit = std::min<std::size_t>(file.bytes.size(), 256);
    const auto *begin = file.bytes.data() + at;
    const auto *end = file.bytes.data() + limit;
    const auto *newline = std::find(begin, end, static_cast<unsigned char>('\n'));
    if (newline == end) {
      problem = "the header does not have four text lines (a truncated or non-.3df file)";
      return false;
    }
    line = trimmed(std::string(begin, newline));
    at = static_cast<std::size_t>(newline - file.bytes.data()) + 1;
  }
  file.body = at;
  if (lines[0].rfind("3df v", 0) != 0) {
    problem = "bad header: the first line is \"" + lines[0] + "\", not \"3df v<version>\"";
    return false;
  }
  const std::string name = upper(lines[1]);
  const auto format = std::find_if(std::begin(kFormatNames), std::end(kFormatNames),
                                   [&](const FormatName &f) { return name == f.name; });
  if (format == std::end(kFormatNames)) {
    problem = "unknown texture format \"" + lines[1] + "\"";
    return false;
  }
  long small_side = 0, large_side = 0, aspect_w = 0, aspect_h = 0;
  char rest = 0;
  if (std::sscanf(lines[2].c_str(), "lod range: %ld %ld %c", &small_side, &large_side, &rest) !=
      2) {
    problem = "bad header: expected \"lod range: <smallest> <largest>\", got \"" + lines[2] + "\"";
    return false;
  }
  const int small_lod = lod_of_side(small_side), large_lod = lod_of_side(large_side);
  if (small_lod < 0 || large_lod < 0 || small_side > large_side) {
    problem = "bad lod range " + std::to_string(small_side) + " " + std::to_string(large_side) +
              " (sides 1..256, powers of two, smallest first)";
    return false;
  }
  if (std::sscanf(lines[3].c_str(), "aspect ratio: %ld %ld %c", &aspect_w, &aspect_h, &rest) !=
      2) {
    problem = "bad header: expected \"aspect ratio: <w> <h>\", got \"" + lines[3] + "\"";
    return false;
  }
  const int aspect = aspect_of(aspect_w, aspect_h);
  if (aspect < 0) {
    problem = "bad aspect ratio " + std::to_string(aspect_w) + " " + std::to_string(aspect_h) +
              " (one side 1, the other 1, 2, 4 or 8)";
    return false;
  }
  Gu3dfHeader &header = file.header;
  header.small_lod = small_lod;
  header.large_lod = large_lod;
  header.aspect_ratio = aspect;
  header.format = format->format;
  const glide_shim::LevelSize top = glide_shim::level_size(large_lod, aspect);
  header.width = static_cast<FxU32>(top.width);
  header.height = static_cast<FxU32>(top.height);
  file.texel_bytes = 0;
  for (int lod = large_lod; lod <= small_lod; ++lod) {
    const glide_shim::LevelSize size = glide_shim::level_size(lod, aspect);
    file.texel_bytes += static_cast<FxU32>(size.width * size.height *
                                           glide_shim::bytes_per_texel(header.format));
  }
  return true;
}

bool is_ncc(GrTextureFormat_t format) {
  return format == GR_TEXFMT_YIQ_422 || format == GR_TEXFMT_AYIQ_8422;
}
bool is_palette(GrTextureFormat_t format) {
  return format == GR_TEXFMT_P_8 || format == GR_TEXFMT_AP_88;
}

FxU16 big_endian16(const unsigned char *p) { return static_cast<FxU16>((p[0] << 8) | p[1]); }
FxU32 big_endian32(const unsigned char *p) {
  return (FxU32{p[0]} << 24) | (FxU32{p[1]} << 16) | (FxU32{p[2]} << 8) | FxU32{p[3]};
}

bool same_header(const Gu3dfHeader &a, const Gu3dfHeader &b) {
  return a.width == b.width && a.height == b.height && a.small_lod == b.small_lod &&
         a.large_lod == b.large_lod && a.aspect_ratio == b.aspect_ratio && a.format == b.format;
}

void report_file(const char *function, const char *filename, const std::string &problem) {
  current().report(GLIDESHIM_ERR_FILE,
                   std::string(function) + ": " + filename + ": " + problem);
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

FxBool gu3dfGetInfo(const char *filename, Gu3dfInfo *info) {
  if (filename == nullptr || info == nullptr) {
    current().report(GLIDESHIM_ERR_NULL_POINTER, "gu3dfGetInfo: filename or info is NULL");
    return FXFALSE;
  }
  ParsedFile file;
  std::string problem;
  if (!parse(filename, file, problem)) {
    report_file("gu3dfGetInfo", filename, problem);
    return FXFALSE;
  }
  info->header = file.header;
  // The bytes gu3dfLoad will write to info->data (programs allocate this much).
  info->mem_required = file.texel_bytes;
  return FXTRUE;
}

FxBool gu3dfLoad(const char *filename, Gu3dfInfo *info) {
  if (filename == nullptr || info == nullptr || info->data == nullptr) {
    current().report(GLIDESHIM_ERR_NULL_POINTER,
                     "gu3dfLoad: filename, info or info->data is NULL (allocate "
                     "info->mem_required bytes after gu3dfGetInfo)");
    return FXFALSE;
  }
  ParsedFile file;
  std::string problem;
  if (!parse(filename, file, problem)) {
    report_file("gu3dfLoad", filename, problem);
    return FXFALSE;
  }
  if (!same_header(file.header, info->header)) {
    current().report(GLIDESHIM_ERR_INCONSISTENT,
                     std::string("gu3dfLoad: ") + filename +
                         ": info->header does not describe this file (call gu3dfGetInfo on it "
                         "first)");
    return FXFALSE;
  }
  const GrTextureFormat_t format = file.header.format;
  const std::size_t table_bytes = is_ncc(format) ? 40 * 2 : is_palette(format) ? 256 * 4 : 0;
  const std::size_t expected = file.body + table_bytes + file.texel_bytes;
  if (file.bytes.size() != expected) {
    problem = file.bytes.size() < expected ? "truncated: " : "wrong size: ";
    report_file("gu3dfLoad", filename,
                problem + std::to_string(file.bytes.size()) + " bytes, expected " +
                    std::to_string(expected) + " (header " + std::to_string(file.body) +
                    ", table " + std::to_string(table_bytes) + ", texels " +
                    std::to_string(file.texel_bytes) + ")");
    return FXFALSE;
  }
  // Everything is known good: fill the caller's table and data.
  const unsigned char *p = file.bytes.data() + file.body;
  if (is_ncc(format)) {
    GuNccTable &ncc = info->table.nccTable;
    for (int i = 0; i < 16; ++i, p += 2) ncc.yRGB[i] = static_cast<FxU8>(big_endian16(p) & 0xFF);
    for (auto *vectors : {ncc.iRGB, ncc.qRGB}) {
      for (int i = 0; i < 4; ++i) {
        for (int c = 0; c < 3; ++c, p += 2) {
          vectors[i][c] = static_cast<FxI16>(big_endian16(p) & 0x1FF);
        }
      }
    }
    // The 12 words the hardware receives: four Y per word, then I and Q as 9-bit R, G, B.
    for (int i = 0; i < 4; ++i) {
      ncc.packed_data[i] = FxU32{ncc.yRGB[4 * i]} | (FxU32{ncc.yRGB[4 * i + 1]} << 8) |
                           (FxU32{ncc.yRGB[4 * i + 2]} << 16) |
                           (FxU32{ncc.yRGB[4 * i + 3]} << 24);
    }
    for (int i = 0; i < 4; ++i) {
      for (int k = 0; k < 2; ++k) {
        const FxI16 *v = k == 0 ? ncc.iRGB[i] : ncc.qRGB[i];
        ncc.packed_data[4 + 4 * k + i] = (static_cast<FxU32>(v[0]) << 18) |
                                         (static_cast<FxU32>(v[1]) << 9) |
                                         static_cast<FxU32>(v[2]);
      }
    }
  } else if (is_palette(format)) {
    for (int i = 0; i < 256; ++i, p += 4) info->table.palette.data[i] = big_endian32(p);
  }
  auto *out = static_cast<unsigned char *>(info->data);
  if (glide_shim::bytes_per_texel(format) == 1) {
    std::memcpy(out, p, file.texel_bytes);
  } else {
    for (FxU32 i = 0; i < file.texel_bytes / 2; ++i, p += 2) {
      const FxU16 texel = big_endian16(p);
      std::memcpy(out + 2 * i, &texel, 2);
    }
  }
  return FXTRUE;
}

}  // namespace glide_shim_api
