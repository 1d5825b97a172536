// Chapter "gu utilities" (gu.c) and the RLE texture download (gtexdl.c): byte and word swaps,
// the RLE16 encoder, the colour-per-level test mip map, and ConvertAndDownloadRle, which
// decodes run-length-coded 8-bit rows through a 16-bit look-up table into part of a texture
// level (written for Descent's bitmaps).
#include "context.h"
#include "texture_layout.h"

#include <glideutl.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using glide_shim::current;

namespace {

// guEncodeRLE16's runs: the driver counts a run in a C short, so no run is longer than this.
constexpr FxU32 kMaxRle16Run = 32767;

// guTexCreateColorMipMap's levels, 256x256 down to 1x1: red, green, blue, white, black, then
// the first four again (gu.c's setlevel calls).
constexpr FxU16 kColorMipMapLevels[9] = {0xF800, 0x07E0, 0x001F, 0xFFFF, 0x0000,
                                         0xF800, 0x07E0, 0x001F, 0xFFFF};

// ConvertAndDownloadRle's byte code (the Watcom decoder in fxglide.h): a byte whose top three
// bits are set starts a run of (byte & 0x1F) copies of the next byte's colour, and a run of 0
// ends the row; any other byte is one texel of that colour index.
constexpr std::uint8_t kRleRunCode = 0xE0;
constexpr std::uint8_t kRleCountMask = 0x1F;
// The driver decodes each row into a line of this many texels.
constexpr FxU32 kRleLineTexels = 256;

// Decodes row `row` of an RLE bitmap (4 bytes the driver skips, one length byte per row, then
// the rows) through `tlut`. Returns false after reporting a row that runs past its length byte
// or decodes to more texels than the driver's line holds.
bool decode_rle_row(const FxU8 *bitmap, long rows, long row, const FxU16 *tlut,
                    std::vector<FxU16> &texels) {
  std::size_t offset = 4 + static_cast<std::size_t>(rows);
  for (long earlier = 0; earlier < row; ++earlier) {
    offset += bitmap[4 + static_cast<std::size_t>(earlier)];
  }
  const std::size_t end = offset + bitmap[4 + static_cast<std::size_t>(row)];
  texels.clear();
  auto problem = [&](const std::string &what) {
    current().report(GLIDESHIM_ERR_INVALID_VALUE,
                     "ConvertAndDownloadRle: bitmap row " + std::to_string(row) + " " + what);
    return false;
  };
  std::size_t at = offset;
  while (true) {
    if (at >= end) return problem("has no end code within its " +
                                  std::to_string(end - offset) + " bytes");
    const std::uint8_t code = bitmap[at++];
    std::size_t count = 1;
    std::uint8_t index = code;
    if ((code & kRleRunCode) == kRleRunCode) {
      count = code & kRleCountMask;
      if (count == 0) return true;
      if (at >= end) return problem("ends inside a run");
      index = bitmap[at++];
    }
    if (texels.size() + count > kRleLineTexels) {
      return problem("decodes to more than " + std::to_string(kRleLineTexels) + " texels");
    }
    texels.insert(texels.end(), count, tlut[index]);
  }
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

FxU32 guEndianSwapWords(FxU32 value) { return (value >> 16) | (value << 16); }

FxU16 guEndianSwapBytes(FxU16 value) {
  return static_cast<FxU16>((value >> 8) | (value << 8));
}

int guEncodeRLE16(void *dst, void *src, FxU32 width, FxU32 height) {
  auto &ctx = current();
  if (src == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "guEncodeRLE16: src is NULL");
    return 0;
  }
  // Every pixel may start a run of its own (4 bytes each); the byte count must fit the int.
  const std::uint64_t pixels = std::uint64_t{width} * height;
  if (pixels > static_cast<std::uint64_t>(INT_MAX / 4)) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "guEncodeRLE16: " + std::to_string(width) + "x" + std::to_string(height) +
                   " pixels could encode to more bytes than the int result holds");
    return 0;
  }
  // RLE16: one 32-bit word per run of equal 565 pixels, the run's length in the high half and
  // the pixel in the low half, runs following the image row by row across row ends. (gu.c's
  // loop counts each run's first pixel twice, so it stops early or reads past the image; this
  // is the encoding it describes.)
  const auto *pixel = static_cast<const FxU16 *>(src);
  auto *out = static_cast<std::uint8_t *>(dst);
  const auto count = static_cast<std::size_t>(pixels);
  int bytes = 0;
  for (std::size_t i = 0; i < count;) {
    const FxU16 color = pixel[i];
    std::size_t run = 1;
    while (i + run < count && run < kMaxRle16Run && pixel[i + run] == color) ++run;
    if (out != nullptr) {
      const FxU32 word = (static_cast<FxU32>(run) << 16) | color;
      std::memcpy(out + bytes, &word, sizeof word);
    }
    bytes += 4;
    i += run;
  }
  return bytes;
}

FxU16 *guTexCreateColorMipMap(void) {
  // Nine levels, 256x256 to 1x1, of RGB 565 texels, packed largest first for
  // grTexDownloadMipMap; the caller frees the block with free().
  std::size_t texels = 0;
  for (int side = 256; side >= 1; side /= 2) texels += static_cast<std::size_t>(side * side);
  auto *data = static_cast<FxU16 *>(std::malloc(texels * sizeof(FxU16)));
  if (data == nullptr) {
    current().report(GLIDESHIM_ERR_OUT_OF_RANGE,
                     "guTexCreateColorMipMap: could not allocate " +
                         std::to_string(texels * sizeof(FxU16)) + " bytes");
    return nullptr;
  }
  FxU16 *level = data;
  int index = 0;
  for (int side = 256; side >= 1; side /= 2, ++index) {
    const auto level_texels = static_cast<std::size_t>(side * side);
    std::fill(level, level + level_texels, kColorMipMapLevels[index]);
    level += level_texels;
  }
  return data;
}

void ConvertAndDownloadRle(GrChipID_t tmu, FxU32 startAddress, GrLOD_t thisLod,
                           GrLOD_t largeLod, GrAspectRatio_t aspectRatio,
                           GrTextureFormat_t format, FxU32 evenOdd, FxU8 *bm_data, long bm_h,
                           FxU32 u0, FxU32 v0, FxU32 width, FxU32 height, FxU32 dest_width,
                           FxU32 dest_height, FxU16 *tlut) {
  const char *name = "ConvertAndDownloadRle";
  auto &ctx = current();
  if (!ctx.require_open(name) || !glide_shim::check_tmu(name, tmu)) return;
  if (bm_data == nullptr || tlut == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, std::string(name) + ": bm_data or tlut is NULL");
    return;
  }
  if (!glide_shim::is_even_odd(evenOdd)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, std::string(name) + ": unknown evenOdd mask");
    return;
  }
  if (!glide_shim::check_texture_info(name, thisLod, largeLod, aspectRatio, format)) return;
  if (glide_shim::bytes_per_texel(format) != 2) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT,
               std::string(name) + ": the look-up table gives 16-bit texels, and format " +
                   std::to_string(format) + " has 8");
    return;
  }
  const glide_shim::LevelSize level = glide_shim::level_size(thisLod, aspectRatio);
  const FxU32 offset =
      glide_shim::level_offset(thisLod, largeLod, aspectRatio, format, evenOdd);
  const auto row_bytes = static_cast<FxU32>(level.width * 2);
  const FxU32 level_bytes = row_bytes * static_cast<FxU32>(level.height);
  if (startAddress % 8 != 0 || startAddress > glide_shim::kTmuMemoryBytes ||
      offset + level_bytes > glide_shim::kTmuMemoryBytes - startAddress) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               std::string(name) + ": the level at start address " +
                   std::to_string(startAddress) + " is misaligned or beyond TMU memory");
    return;
  }
  // The rectangle: bitmap rows v0..v0+height-1, texels u0.. of each, into level rows
  // 0..height-1 (plus one more, a copy of the last, when dest_height > height), each row's
  // first dest_width texels rounded down to pairs (the driver writes texel pairs).
  std::string problem;
  if (dest_width == 0 || dest_width > static_cast<FxU32>(level.width) || dest_height == 0 ||
      dest_height > static_cast<FxU32>(level.height)) {
    problem = "the destination " + std::to_string(dest_width) + "x" +
              std::to_string(dest_height) + " is empty or larger than the " +
              std::to_string(level.width) + "x" + std::to_string(level.height) + " level";
  } else if (height == 0 || height > dest_height) {
    problem = "height " + std::to_string(height) + " is 0 or more than dest_height " +
              std::to_string(dest_height);
  } else if (bm_h < 0 || std::uint64_t{v0} + height > static_cast<std::uint64_t>(bm_h)) {
    problem = "rows " + std::to_string(v0) + ".." + std::to_string(std::uint64_t{v0} + height - 1) +
              " are not all among the bitmap's " + std::to_string(bm_h);
  } else if (std::uint64_t{u0} + width > kRleLineTexels ||
             std::uint64_t{u0} + dest_width > kRleLineTexels) {
    problem = "u0 + width and u0 + dest_width must stay within the driver's " +
              std::to_string(kRleLineTexels) + "-texel row";
  }
  if (!problem.empty()) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, std::string(name) + ": " + problem);
    return;
  }
  // The driver skips a level the evenOdd mask leaves out (it lives on the other TMU).
  if (!glide_shim::level_selected(thisLod, evenOdd)) return;

  const FxU32 texels_per_row = dest_width & ~1u;
  const FxU32 rows_written = height + (dest_height > height ? 1u : 0u);
  // The level's current rows, so texels right of the rectangle keep their values.
  std::vector<FxU16> rows(static_cast<std::size_t>(rows_written) *
                          static_cast<std::size_t>(level.width));
  std::memcpy(rows.data(), ctx.tmu.memory.data() + startAddress + offset,
              rows.size() * sizeof(FxU16));
  std::vector<FxU16> decoded;
  for (FxU32 t = 0; t < height; ++t) {
    if (!decode_rle_row(bm_data, bm_h, static_cast<long>(v0 + t), tlut, decoded)) return;
    if (decoded.size() < std::size_t{u0} + texels_per_row) {
      ctx.report(GLIDESHIM_ERR_INVALID_VALUE,
                 std::string(name) + ": bitmap row " + std::to_string(v0 + t) + " decodes to " +
                     std::to_string(decoded.size()) + " texels, fewer than u0 + " +
                     std::to_string(texels_per_row));
      return;
    }
    std::copy_n(decoded.begin() + u0, texels_per_row,
                rows.begin() + static_cast<std::ptrdiff_t>(t) * level.width);
  }
  if (rows_written > height) {  // the extra row repeats the last decoded one
    const auto last = rows.begin() + static_cast<std::ptrdiff_t>(height - 1) * level.width;
    std::copy_n(last, texels_per_row, last + level.width);
  }
  grTexDownloadMipMapLevelPartial(tmu, startAddress, thisLod, largeLod, aspectRatio, format,
                                  evenOdd, rows.data(), 0, static_cast<int>(rows_written) - 1);
}

}  // namespace glide_shim_api
