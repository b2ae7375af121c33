#!/usr/bin/env python3
"""Writes the PNG fixtures of png_read_test.cpp: small files in colour types and bit depths
clrt never writes itself, built chunk by chunk so they do not depend on libpng. No gAMA, sRGB or
other colour chunks, so readers must take the samples as they are. Run from this directory."""
import struct
import zlib


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))


def png(width, height, bit_depth, colour_type, rows, extra_chunks=()):
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    raw = b"".join(b"\x00" + row for row in rows)  # filter type 0 (None) on every row
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + b"".join(extra_chunks) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def write(name, data):
    with open(name, "wb") as f:
        f.write(data)


# 16-bit RGB, 2x1: (0x1234, 0x8080, 0xffff) (0x0000, 0x12c0, 0xfeff)
write("rgb16.png", png(2, 1, 16, 2, [struct.pack(">6H", 0x1234, 0x8080, 0xFFFF, 0x0000, 0x12C0, 0xFEFF)]))

# 2-bit palette, 4x1, indices 0 1 2 3; entry 1 is half transparent through tRNS.
palette = bytes([255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30])
write("palette2.png", png(4, 1, 2, 3, [bytes([0b00011011])],
                          [chunk(b"PLTE", palette), chunk(b"tRNS", bytes([255, 128]))]))

# 1-bit grey, 8x1: 1 0 1 1 0 0 0 1
write("gray1.png", png(8, 1, 1, 0, [bytes([0b10110001])]))

# 8-bit grey + alpha, 2x1: (100, 50) (200, 255)
write("gray_alpha8.png", png(2, 1, 8, 4, [bytes([100, 50, 200, 255])]))
