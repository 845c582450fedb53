#!/usr/bin/env python3
"""CPU time to a relMSE, Glint against Cycles, from one sitting's raw data.

usage: time_to_error.py GLINT.csv CYCLES.csv [--sitting NAME] [--pixels N]

GLINT.csv: sitting, scene, bounces, round, config, args, cpu_seconds, relmse; one row per
`glint render`. A config is [bK]uN (N spp, uniform) or [bK]mT (adaptive goal mean at threshold T),
bK naming K x K sample blocks (none: no blocks); `fixed` rows (older sittings) are ignored.
CYCLES.csv: sitting, scene, bounces, [round,] samples, wall_seconds, cpu_seconds, relmse; one row
per cornell_cycles.py render.

Rounds are reduced to medians per config (Glint) or sample count (Cycles). Each renderer's fixed
cost (process start, scene, shaders, file writing) is the intercept of a least-squares line of CPU
time against samples over its uniform renders (per block size for Glint), and is taken off every
render; the slope is the CPU time per sample. Times to each relMSE are log-log interpolated between
measured points; a target outside a series' points is left blank. Prints two Markdown tables: per
sample, and CPU seconds to each relMSE with the ratios to Cycles.
"""
import argparse
import collections
import csv
import math
import re
import statistics

TARGETS = (1e-2, 5e-3, 1e-3, 5e-4)
CONFIG = re.compile(r"^(?:b(\d+))?([um])([0-9.]+)$")


def interpolate(points, target):
    # A render shorter than the fitted fixed cost (timing noise at a few samples) has no place on a log scale.
    points = sorted((t, e) for t, e in points if t > 0)
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if (e0 - target) * (e1 - target) <= 0 and e0 != e1:
            a = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + a * (math.log(t1) - math.log(t0)))
    return None


def fit_line(points):
    n = len(points)
    mx = sum(x for x, _ in points) / n
    my = sum(y for _, y in points) / n
    slope = sum((x - mx) * (y - my) for x, y in points) / sum((x - mx) ** 2 for x, _ in points)
    return my - slope * mx, slope


def fmt(x, digits=2):
    return "" if x is None else f"{x:.{digits}f}"


def series_name(block, kind):
    name = "uniform" if kind == "u" else "goal mean"
    return name if block == 1 else f"{block}x{block} blocks, {name}"


class Glint:
    """One scene's Glint renders: per series (block, kind) the (CPU s less the fixed cost, relMSE) points."""

    def __init__(self, rows):
        medians = {}
        for config, runs in rows.items():
            m = CONFIG.match(config)
            if m:
                key = (int(m.group(1) or 1), m.group(2), float(m.group(3)))
                medians[key] = (statistics.median(t for t, _ in runs), statistics.median(e for _, e in runs))
        self.fixed, self.slope, self.at64, self.series = {}, {}, {}, collections.defaultdict(list)
        for block in sorted({b for b, _, _ in medians}):
            uniform = [(n, t) for (b, k, n), (t, _) in medians.items() if b == block and k == "u"]
            if len(uniform) >= 2:
                self.fixed[block], self.slope[block] = fit_line(uniform)
            self.at64[block] = medians.get((block, "u", 64.0), (None, None))[1]
        for (block, kind, _), (t, e) in medians.items():
            fixed = self.fixed.get(block, self.fixed.get(1, 0.0))
            self.series[(block, kind)].append((t - fixed, e))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("glint")
    p.add_argument("cycles")
    p.add_argument("--sitting", help="only this sitting's rows (default: all, per sitting)")
    p.add_argument("--pixels", type=int, default=128 * 128, help="pixels per image, for paths per CPU second")
    args = p.parse_args()

    glint = collections.defaultdict(lambda: collections.defaultdict(list))
    for r in csv.DictReader(open(args.glint)):
        if args.sitting and r["sitting"] != args.sitting:
            continue
        glint[(r["sitting"], r["scene"], int(r["bounces"]))][r["config"]].append((float(r["cpu_seconds"]), float(r["relmse"])))
    cycles_runs = collections.defaultdict(lambda: collections.defaultdict(list))
    for r in csv.DictReader(open(args.cycles)):
        cycles_runs[(r["sitting"], r["scene"], int(r["bounces"]))][int(r["samples"])].append(
            (float(r["cpu_seconds"]), float(r["relmse"])))

    keys = [k for k in sorted(glint) if k in cycles_runs]
    found = {k: Glint(glint[k]) for k in keys}
    blocks = sorted({b for g in found.values() for b in g.slope})
    cycles = {}
    for key in keys:
        med = {n: (statistics.median(t for t, _ in v), statistics.median(e for _, e in v)) for n, v in cycles_runs[key].items()}
        fixed, slope = fit_line([(n, t) for n, (t, _) in med.items()])
        cycles[key] = (slope, med.get(64, (None, None))[1], [(t - fixed, e) for t, e in med.values()])

    names = [series_name(b, "u") for b in blocks]
    print("| sitting | scene | bounces | CPU ms per sample: " + " / ".join(f"Glint {n}" for n in names) +
          " / Cycles | M paths per CPU s: same order | relMSE at 64 spp: same order |")
    print("|---|---|---|---|---|---|")
    for key in keys:
        g, (c_slope, c64, _) = found[key], cycles[key]
        slopes = [g.slope.get(b) for b in blocks] + [c_slope]
        errors = [g.at64.get(b) for b in blocks] + [c64]
        print(f"| {key[0]} | {key[1]} | {key[2]} | " + " / ".join(fmt(s and s * 1000, 1) for s in slopes) + " | " +
              " / ".join(fmt(s and args.pixels / s / 1e6, 3) for s in slopes) + " | " +
              " / ".join("" if e is None else f"{e:.2e}" for e in errors) + " |")
    print()

    series = sorted({s for g in found.values() for s in g.series}, key=lambda s: (s[0], s[1] == "m"))
    names = [series_name(*s) for s in series]
    print("| sitting | scene | bounces | relMSE | CPU s: " + " / ".join(f"Glint {n}" for n in names) +
          " / Cycles | Glint / Cycles: " + " / ".join(names) + " |")
    print("|---|---|---|---|---|---|")
    for key in keys:
        g, (_, _, cyc) = found[key], cycles[key]
        for target in TARGETS:
            c = interpolate(cyc, target)
            times = [interpolate(g.series.get(s, []), target) for s in series]
            if c is None or all(t is None for t in times):
                continue  # the target lies outside the measured points
            ratios = [None if t is None else t / c for t in times]
            print(f"| {key[0]} | {key[1]} | {key[2]} | {target:g} | " + " / ".join(fmt(t) for t in times + [c]) +
                  " | " + " / ".join(fmt(r) for r in ratios) + " |")


if __name__ == "__main__":
    main()
