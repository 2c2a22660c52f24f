#!/usr/bin/env python3
"""Decodes a PNG with the standard library only and prints "WIDTH HEIGHT DISTINCT_COLOURS BRIGHT_SHARE DARK_SHARE".
Exits 1 (with the reason) when the file is not a PNG that decodes. Used by the editor's end-to-end test."""
import struct
import sys
import zlib


def decode(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG signature")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or interlace != 0 or colour not in (0, 2, 4, 6):
        raise ValueError(f"unsupported PNG (depth {depth}, colour type {colour}, interlace {interlace})")
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = prev[x], prev[x - channels] if x >= channels else 0
            if kind == 1: line[x] = (line[x] + a) & 255
            elif kind == 2: line[x] = (line[x] + b) & 255
            elif kind == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def main():
    try:
        width, height, channels, rows = decode(sys.argv[1])
    except Exception as error:  # any failure to decode is the answer
        print(f"{sys.argv[1]}: does not decode: {error}")
        return 1
    colours, bright, dark, n = set(), 0, 0, 0
    for row in rows[::4]:
        for x in range(0, width * channels, channels * 4):
            px = tuple(row[x:x + min(channels, 3)])
            colours.add(px)
            bright += px[0] > 150
            dark += px[0] < 60
            n += 1
    print(width, height, len(colours), f"{bright / n:.3f}", f"{dark / n:.3f}")
    return 0


sys.exit(main())
