#!/usr/bin/env python3
"""Packs PNG icons into one Windows .ico (PNG entries, as Windows Vista and later read them).

    make-ico.py OUT.ico 16.png 24.png 32.png 48.png 256.png

Each PNG must be square and at most 256 pixels wide; the size comes from its header.
"""
import struct
import sys


def png_size(data, path):
    if data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR":
        sys.exit(f"make-ico: {path} is not a PNG")
    width, height = struct.unpack(">II", data[16:24])
    if width != height or width > 256:
        sys.exit(f"make-ico: {path} is {width}x{height}, not square up to 256")
    return width


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, pngs = sys.argv[1], sys.argv[2:]
    images = []
    for path in pngs:
        with open(path, "rb") as f:
            data = f.read()
        images.append((png_size(data, path), data))
    header = struct.pack("<HHH", 0, 1, len(images))  # reserved, type 1 = icon, count
    offset = len(header) + 16 * len(images)
    entries, blobs = b"", b""
    for size, data in images:
        # width and height 0 mean 256; no palette; 1 plane, 32 bits per pixel
        entries += struct.pack("<BBBBHHII", size % 256, size % 256, 0, 0, 1, 32, len(data), offset)
        blobs += data
        offset += len(data)
    with open(out, "wb") as f:
        f.write(header + entries + blobs)


if __name__ == "__main__":
    main()
