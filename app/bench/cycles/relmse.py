#!/usr/bin/env python3
"""relMSE of images against a reference, as docs/CLI.md defines it for `glint bench`: the mean over
pixels and RGB of (x - r)^2 / (r^2 + 0.01).

usage: relmse.py REFERENCE.exr IMAGE.exr...   (prints one line per image: path relMSE)
Needs python3-numpy and python3-openimageio (Debian).
"""
import sys

import numpy
import OpenImageIO as oiio


def read_rgb(path):
    image = oiio.ImageBuf(path)
    if image.has_error:
        sys.exit(f"relmse.py: {path}: {image.geterror()}")
    return image.get_pixels(oiio.FLOAT)[..., :3]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    reference = read_rgb(sys.argv[1])
    for path in sys.argv[2:]:
        image = read_rgb(path)
        if image.shape != reference.shape:
            sys.exit(f"relmse.py: {path}: {image.shape[1]}x{image.shape[0]}, the reference is {reference.shape[1]}x{reference.shape[0]}")
        print(path, float(numpy.mean((image - reference) ** 2 / (reference * reference + 0.01))))


if __name__ == "__main__":
    main()
