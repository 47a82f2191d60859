"""An 8-bit PNG writer in the standard library alone, for the tools that make the example
textures (make_window_texture.py, make_rust_mask.py), so that they run anywhere."""
import struct
import zlib

COLOUR_TYPES = {1: 0, 3: 2, 4: 6}  # channels -> PNG colour type: grey, RGB, RGBA


def png8(width, height, rows, channels=3):
    """The bytes of a PNG of `rows` (top first), each `width` * `channels` values in [0, 255]."""
    def chunk(kind, data):
        return (struct.pack('>I', len(data)) + kind + data +
                struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff))
    raw = b''.join(b'\x00' + bytes(row) for row in rows)
    header = struct.pack('>IIBBBBB', width, height, 8, COLOUR_TYPES[channels], 0, 0, 0)
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) +
            chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))
