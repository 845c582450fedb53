#!/usr/bin/env python3
"""CPU time to a relMSE, Glint against Cycles, from one sitting's raw data.

usage: time_to_error.py GLINT.csv CYCLES.csv [--sitting NAME]

GLINT.csv: sitting, scene, bounces, round, config, args, cpu_seconds, relmse; one row per
`glint render` (configs uN: N spp uniform; mT: adaptive goal mean; fixed: 4 spp).
CYCLES.csv: sitting, scene, bounces, samples, wall_seconds, cpu_seconds, relmse; one row per
cornell_cycles.py render.

Each renderer's fixed cost (process start, scene, shaders, file writing) is the intercept of a
least-squares line of CPU time against samples over its uniform renders, and is taken off every
render; Glint's rounds are reduced to medians. Times to each relMSE are log-log interpolated between
measured points; a target outside either renderer's points is left out. Prints a Markdown table.
"""
import argparse
import collections
import csv
import math
import statistics

TARGETS = (1e-2, 5e-3, 1e-3, 5e-4)


def interpolate(points, target):
    points = sorted(points)
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


def main():
    p = argparse.ArgumentParser()
    p.add_argument("glint")
    p.add_argument("cycles")
    p.add_argument("--sitting", help="only this sitting's rows (default: all, per sitting)")
    args = p.parse_args()

    glint = collections.defaultdict(lambda: collections.defaultdict(list))
    for r in csv.DictReader(open(args.glint)):
        if args.sitting and r["sitting"] != args.sitting:
            continue
        key = (r["sitting"], r["scene"], int(r["bounces"]))
        glint[key][r["config"]].append((float(r["cpu_seconds"]), float(r["relmse"])))
    cycles = collections.defaultdict(list)
    for r in csv.DictReader(open(args.cycles)):
        key = (r["sitting"], r["scene"], int(r["bounces"]))
        cycles[key].append((int(r["samples"]), float(r["cpu_seconds"]), float(r["relmse"])))

    print("| sitting | scene | bounces | ms/sample Glint / Cycles | relMSE at 64 spp Glint / Cycles | "
          "relMSE | Glint uniform s | Glint goal mean s | Cycles s | uniform / Cycles | goal mean / Cycles |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for key in sorted(glint):
        if key not in cycles:
            continue
        runs = {c: (statistics.median(t for t, _ in v), statistics.median(e for _, e in v)) for c, v in glint[key].items()}
        uniform = {int(c[1:]): v for c, v in runs.items() if c.startswith("u")}
        g_fixed, g_slope = fit_line([(n, t) for n, (t, _) in uniform.items()])
        uni = [(t - g_fixed, e) for t, e in uniform.values()]
        goal = [(t - g_fixed, e) for c, (t, e) in runs.items() if c.startswith("m")]
        c_fixed, c_slope = fit_line([(n, t) for n, t, _ in cycles[key]])
        cyc = [(t - c_fixed, e) for _, t, e in cycles[key]]
        g64 = uniform.get(64, (None, None))[1]
        c64 = next((e for n, _, e in cycles[key] if n == 64), None)
        head = (f"| {key[0]} | {key[1]} | {key[2]} | {g_slope * 1000:.1f} / {c_slope * 1000:.1f} | "
                f"{g64:.2e} / {c64:.2e} |")
        for target in TARGETS:
            u, m, c = interpolate(uni, target), interpolate(goal, target), interpolate(cyc, target)
            ratio = lambda x: None if x is None or c is None else x / c
            if ratio(u) is None and ratio(m) is None:
                continue  # the target lies outside one renderer's measured points
            print(f"{head} {target:g} | {fmt(u)} | {fmt(m)} | {fmt(c)} | {fmt(ratio(u))} | {fmt(ratio(m))} |")


if __name__ == "__main__":
    main()
