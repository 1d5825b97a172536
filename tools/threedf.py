"""The pieces of a .3df texture file, as 3dfx's texture tools wrote them and gu3dfGetInfo reads
them: four text header lines, then the format's tables (a P8 or AP88 palette, a YIQ NCC table),
then every mip-map level largest first, row-major. Multi-byte values are big-endian. Shared by
the scripts that make the example programs' and the SDK tests' textures."""
import struct


def header(format_name, smallest, largest, aspect):
    """The header lines: format name as gu3df spells it ("rgb565", "p8", "yiq"), the LOD range
    as the smallest and largest side in texels, the aspect ratio as "W H"."""
    return f"3df v1.1\n{format_name}\nlod range: {smallest} {largest}\naspect ratio: {aspect}\n".encode()


def words16(values):
    """16-bit texels or NCC table entries, big-endian (negative values as two's complement)."""
    return b"".join(struct.pack(">H", v & 0xFFFF) for v in values)


def palette(entries):
    """256 palette entries (r, g, b) 0..255 as big-endian 0x00RRGGBB words."""
    return b"".join(struct.pack(">I", r << 16 | g << 8 | b) for r, g, b in entries)
