#!/usr/bin/env python3
"""Writes the .3df textures crate_3df reads (examples/data/), as 3dfx's texture tools wrote them:
four header lines, the palette for P8 (256 big-endian 0x00RRGGBB words), then every mip-map
level largest first, row-major; 16-bit texels big-endian, 8-bit texels as bytes.
Deterministic: running it again rebuilds the same bytes.

    python3 examples/data/make_textures.py examples/data

  crate.3df  RGB565, 64x64 down to 1x1: planks with a frame and a diagonal brace
  floor.3df  P8, 64x64 down to 1x1: tiles through a warm palette, grout a darker entry
  logo.3df   ARGB4444, 64x32, one level: the letters "GLIDE" on a half-transparent plate
"""
import struct
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
from threedf import header, palette  # noqa: E402


def box_filter(level, side, channels):
    """Halves a square level of per-texel channel tuples by averaging 2x2 blocks."""
    half = side // 2
    smaller = []
    for y in range(half):
        for x in range(half):
            block = [level[(2 * y + dy) * side + 2 * x + dx] for dy in (0, 1) for dx in (0, 1)]
            smaller.append(tuple(sum(t[c] for t in block) // 4 for c in range(channels)))
    return smaller


def crate_texel(x, y):
    """8-bit RGB of the crate face at texel (x, y) of 64x64."""
    frame = x < 6 or x > 57 or y < 6 or y > 57
    brace = abs(x - y) < 5
    if frame or brace:
        shade = 150 + ((x * 7 + y * 3) % 16)
        return (shade, shade * 3 // 4, shade // 3)
    plank = y // 13
    grain = ((x * 5 + plank * 17) % 23) * 2
    seam = y % 13 == 0
    base = 90 if seam else 170 + grain - plank * 6
    return (base, base * 2 // 3, base // 3)


def crate():
    out = header("rgb565", 1, 64, "1 1")
    level = [crate_texel(x, y) for y in range(64) for x in range(64)]
    side = 64
    while True:
        for r, g, b in level:
            out += struct.pack(">H", (r >> 3) << 11 | (g >> 2) << 5 | (b >> 3))
        if side == 1:
            return out
        level = box_filter(level, side, 3)
        side //= 2


def floor_palette():
    """Entry 0 is the grout; 1..255 run from terracotta to sand."""
    entries = [(40, 32, 28)]
    for i in range(1, 256):
        t = i / 255.0
        entries.append((int(150 + 90 * t), int(70 + 120 * t), int(40 + 90 * t)))
    return entries


def floor():
    colours = floor_palette()
    out = header("p8", 1, 64, "1 1")
    out += palette(colours)
    side = 64
    while side >= 1:
        # Each level is made at its own size (a palette index does not average): 4x4 tiles
        # with a grout line of one texel down to 16x16, plain tile colours below that.
        tile = side // 4
        for y in range(side):
            for x in range(side):
                grout = tile >= 4 and (x % tile == 0 or y % tile == 0)
                shade = 60 + ((x // max(tile, 1)) * 53 + (y // max(tile, 1)) * 97) % 190
                out += bytes([0 if grout else shade])
        side //= 2
    return out


# 5x7 glyphs of G, L, I, D, E: one string of five bits per row.
GLYPHS = {
    "G": ["01110", "10001", "10000", "10111", "10001", "10001", "01110"],
    "L": ["10000", "10000", "10000", "10000", "10000", "10000", "11111"],
    "I": ["01110", "00100", "00100", "00100", "00100", "00100", "01110"],
    "D": ["11110", "10001", "10001", "10001", "10001", "10001", "11110"],
    "E": ["11111", "10000", "10000", "11110", "10000", "10000", "11111"],
}


def logo():
    out = header("argb4444", 64, 64, "2 1")
    word = "GLIDE"
    for y in range(32):
        for x in range(64):
            # Glyphs at 2x: 10x14 texels each, 12 texels apart, from (2, 9).
            lit = False
            gx, gy = (x - 2) // 2, (y - 9) // 2
            letter = (x - 2) // 12
            if 0 <= letter < len(word) and 0 <= gy < 7 and (x - 2) % 12 < 10:
                lit = GLYPHS[word[letter]][gy][gx - letter * 6] == "1"
            a, r, g, b = (15, 15, 15, 15) if lit else (7, 1, 2, 6)
            out += struct.pack(">H", a << 12 | r << 8 | g << 4 | b)
    return out


def main():
    directory = Path(sys.argv[1] if len(sys.argv) > 1 else "examples/data")
    directory.mkdir(parents=True, exist_ok=True)
    (directory / "crate.3df").write_bytes(crate())
    (directory / "floor.3df").write_bytes(floor())
    (directory / "logo.3df").write_bytes(logo())


if __name__ == "__main__":
    main()
