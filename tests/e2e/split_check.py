#!/usr/bin/env python3
"""An A/B picture of builtin:grazing, acne (A, left) vs default (B, right): the left half of the plane is striped
(many grey levels in a row), the right half flat. Prints why and exits 1 otherwise."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_check import decode  # noqa: E402


def main(path):
    width, height, channels, rows = decode(path)
    y = height * 2 // 3  # below the label boxes, across the plane
    row = rows[y]
    def greys(x0, x1):
        return len({row[x * channels] for x in range(x0, x1)})
    left, right = greys(width // 4, width // 2 - 4), greys(width // 2 + 4, width * 3 // 4)
    if left < 8 or right > 4:
        print(f"grey levels on row {y}: left {left} (want >= 8, striped), right {right} (want <= 4, flat)")
        return 1
    return 0


sys.exit(main(sys.argv[1]))
