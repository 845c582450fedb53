"""Brightness agreement of two linear EXRs of the same view (Glint's and Cycles' converged images).

Usage:
  blender -b --factory-startup --python app/bench/cycles/compare_brightness.py -- GLINT.exr CYCLES.exr [--grid 3]

Prints the mean RGB and luminance of each image, the ratio Glint / Cycles, and the luminance ratio per
region of a grid x grid split (row 0 at the top), each with +-2 sigma: sigma is the standard error of
the mean per-pixel difference (pixel noise is independent between pixels; a spatially varying
systematic difference only makes it larger, so the bound is conservative). Blender is used as the
Python runtime because it reads EXR and ships numpy.
"""
import argparse
import sys

import bpy
import numpy


def read_rgb(path):
    image = bpy.data.images.load(path, check_existing=False)
    image.colorspace_settings.name = "Non-Color"
    width, height = image.size
    pixels = numpy.empty(width * height * 4, dtype=numpy.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    return pixels.reshape(height, width, 4)[::-1, :, :3].astype(numpy.float64)  # rows top-down


def luminance(rgb):
    return rgb @ numpy.array([0.2126, 0.7152, 0.0722])


def ratio_with_error(a, b):
    """Mean(a) / mean(b) and 2 sigma of that ratio from the per-pixel differences."""
    diff = (a - b).ravel()
    sigma = diff.std(ddof=1) / numpy.sqrt(diff.size) / b.mean()
    return a.mean() / b.mean(), 2.0 * sigma


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="compare_brightness.py")
    p.add_argument("glint")
    p.add_argument("cycles")
    p.add_argument("--grid", type=int, default=3)
    args = p.parse_args(argv)
    glint, cycles = read_rgb(args.glint), read_rgb(args.cycles)
    if glint.shape != cycles.shape:
        raise SystemExit("compare_brightness.py: sizes differ: %s vs %s" % (glint.shape, cycles.shape))
    print("| image | mean R | mean G | mean B | mean Y |\n|---|---|---|---|---|")
    for name, image in (("Glint", glint), ("Cycles", cycles)):
        r, g, b = image.reshape(-1, 3).mean(axis=0)
        print("| %s | %.5f | %.5f | %.5f | %.5f |" % (name, r, g, b, luminance(image).mean()))
    channels = [ratio_with_error(glint[..., c], cycles[..., c]) for c in range(3)]
    y = ratio_with_error(luminance(glint), luminance(cycles))
    print("| Glint / Cycles | %s | %.4f +- %.4f |\n" % (" | ".join("%.4f +- %.4f" % c for c in channels), *y))
    n = args.grid
    height, width = glint.shape[:2]
    print("Luminance ratio Glint / Cycles per region (row 0 at the top):\n")
    print("| row | " + " | ".join("col %d" % c for c in range(n)) + " |\n|---|" + "---|" * n)
    for row in range(n):
        cells = []
        for col in range(n):
            ys = slice(row * height // n, (row + 1) * height // n)
            xs = slice(col * width // n, (col + 1) * width // n)
            cells.append("%.3f +- %.3f" % ratio_with_error(luminance(glint[ys, xs]), luminance(cycles[ys, xs])))
        print("| %d | %s |" % (row, " | ".join(cells)))


main()
