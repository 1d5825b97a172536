// The SST-1's linear-frame-buffer data words, as lfb.cpp's locks and region writes read and write
// them: each write mode's pixel size and fields under lfbMode's RGBA lanes (grLfbWriteColorFormat),
// and grLfbWriteColorSwizzle's byte swizzle and word swap (MAME's expand_lfb_data and
// internal_lfb_w). Pure functions of the data and the layout; no GL.
#pragma once

#include "context.h"
#include "lfb_pipeline.h"

#include <cstdint>

namespace glide_shim {

// Bytes per pixel of an LFB write mode (2 or 4), and what its pixels carry.
int lfb_write_mode_bytes(GrLfbWriteMode_t mode);
bool lfb_mode_has_color(GrLfbWriteMode_t mode);
bool lfb_mode_has_depth(GrLfbWriteMode_t mode);

// One data word (a 16-bit mode's in the low half) expanded to 8-bit colour and a depth code;
// the constants stand in for what the mode does not carry.
LfbPixel expand_lfb_data(GrLfbWriteMode_t mode, GrColorFormat_t lanes, std::uint32_t data,
                         GrAlpha_t constant_alpha, FxU16 constant_depth);
// The data word standing for a stored 565 colour and depth code (alpha full).
std::uint32_t encode_lfb_data(GrLfbWriteMode_t mode, GrColorFormat_t lanes, std::uint16_t word,
                              FxU16 code);
// 8-bit colour truncated to 565, as direct LFB writes store it (no dither).
std::uint16_t truncate_to_565(const Rgba8 &color);

// A pixel's data of `bytes` (2 or 4) bytes, in the machine's byte order as the program wrote
// it, from and to the program's block.
std::uint32_t load_lfb_data(const std::uint8_t *p, int bytes);
void store_lfb_data(std::uint32_t value, std::uint8_t *p, int bytes);
// The swizzle and swap on one pixel's data, and the column a pixel written at `x` lands in.
std::uint32_t swizzled_lfb_data(std::uint32_t data, int bytes, const LfbWriteLayout &layout);
int lfb_landing_x(int x, int bytes, const LfbWriteLayout &layout);

}  // namespace glide_shim
