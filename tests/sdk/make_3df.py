#!/usr/bin/env python3
"""Writes the .3df texture files the texture test programs load (tests/sdk/data/), from the
format's description: four header lines, the NCC table (YIQ formats; 16 Y, 12 I and 12 Q values
as big-endian 16-bit words) or 256 big-endian 32-bit palette entries (P8, AP88), then every
level largest first, row-major, 16-bit texels big-endian. Deterministic; run it again to
rebuild the files:

    python3 tests/sdk/make_3df.py tests/sdk/data
"""
import colorsys
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
from threedf import header, palette, words16  # noqa: E402


def yiq_mipmap():
    """YIQ_422, 64x64 down to 1x1: a diagonal Y ramp under I/Q bands whose phase moves with
    the level, so each level of the chain is told apart on screen."""
    y_table = [min(255, i * 17) for i in range(16)]
    i_table = [(0, 0, 0), (60, -20, -40), (-60, 20, 40), (30, 30, -60)]
    q_table = [(0, 0, 0), (-30, 40, 10), (30, -40, -10), (50, -50, 50)]
    out = header("yiq", 1, 64, "1 1")
    out += words16(y_table)
    for table in (i_table, q_table):
        for vector in table:
            out += words16(vector)
    level = 0
    side = 64
    while side >= 1:
        for y in range(side):
            for x in range(side):
                y_index = ((x + y) * 16) // (2 * side)
                i_index = ((x * 4) // side + level) % 4
                q_index = ((y * 4) // side + level) % 4
                out += bytes([(y_index << 4) | (i_index << 2) | q_index])
        side //= 2
        level += 1
    return out


def p8_stripes():
    """P_8, 64x32 (aspect 2:1), one level: diagonal stripes through a 256-entry hue palette."""
    out = header("p8", 64, 64, "2 1")
    hues = [colorsys.hsv_to_rgb(i / 256.0, 0.8, 1.0) for i in range(256)]
    out += palette([(int(r * 255), int(g * 255), int(b * 255)) for r, g, b in hues])
    for y in range(32):
        for x in range(64):
            out += bytes([(x * 4 + y * 2) & 0xFF])
    return out


def main():
    directory = Path(sys.argv[1] if len(sys.argv) > 1 else "tests/sdk/data")
    directory.mkdir(parents=True, exist_ok=True)
    (directory / "yiq_mipmap.3df").write_bytes(yiq_mipmap())
    (directory / "p8_stripes.3df").write_bytes(p8_stripes())


if __name__ == "__main__":
    main()
