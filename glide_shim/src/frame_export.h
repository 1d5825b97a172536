// Turning a 565 colour buffer into what a monitor showed: 8-bit RGB through the Voodoo's gamma
// table, written as PNG. Used by glideShimWritePng and by the GLIDESHIM_DUMP_DIR frame dump.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace glide_shim {

// The scanned-out 8-bit RGB of 565 pixels: replicate each channel to 8 bits, then look it up in
// the 33-entry gamma CLUT Glide loads (every 8th value of round(255*(x/255)^(1/gamma)), entry
// 32 white) with MAME's linear interpolation between entries.
std::vector<std::uint8_t> scan_out(const std::vector<std::uint16_t> &pixels, float gamma);

// Writes 8-bit RGB rows (top first) as a PNG; false with `error` set on failure.
bool write_png(const std::string &path, int width, int height,
               const std::vector<std::uint8_t> &rgb, std::string &error);

}  // namespace glide_shim
