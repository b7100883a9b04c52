#!/usr/bin/env python3
"""Line-sink pipes against the resolved wall: speed, as a user runs them.

  python3 bench/line_sink.py                    # the main job, 5 interleaved pairs
  python3 bench/line_sink.py --full-ring        # also the full 26-pipe ring without symmetry (1 pair)
  python3 bench/line_sink.py --as-built         # also the shipped as-built shaft (1 pair)

Each pair runs the shipped project as it is (resolved wall, the default
cloud) and then with "pipe": {"model": "line"} on a lattice of
LINE_SPACING, `frostwall --threads 2 run`, VTK and report as shipped, in a
temporary directory. Prints medians of the wall seconds, the median of the
pairwise ratios line / resolved, and the closure day and OB thickness at
60 days of each.
"""
import argparse, json, os, statistics, tempfile

import convergence

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
LINE_SPACING = 0.05
LINE = {"pipe": {"model": "line"}, "numerics": {"placement": "lattice", "spacing": LINE_SPACING}}


def merged(base, patch):
    out = dict(base)
    for k, v in patch.items():
        out[k] = merged(base.get(k, {}), v) if isinstance(v, dict) and isinstance(base.get(k), dict) else v
    return out


def run(name, patch, work, tag):
    with open(os.path.join(ROOT, "projects", name + ".json")) as f:
        project = json.load(f)
    project = merged(project, patch)
    out = os.path.join(work, f"{name}_{tag}")
    project["output"]["directory"] = out
    if "survey" in project:  # its file, from the project's folder
        project["survey"]["file"] = os.path.join(ROOT, "projects", project["survey"]["file"])
    wall, s = convergence.run_project(project, out, 2, EXE)
    ob60 = next((w["OB"]["thickness"] for w in s.get("wall", []) if round(w["day"]) == 60), None)
    return wall, s.get("closure_time_days"), ob60, s.get("run", {}).get("particles")


def pairs(name, patch_a, patch_b, repeats, work):
    a, b = [], []
    for k in range(repeats):
        a.append(run(name, patch_a, work, f"resolved{k}"))
        b.append(run(name, patch_b, work, f"line{k}"))
    ratio = statistics.median(y[0] / x[0] for x, y in zip(a, b))

    def line(label, r):
        wall = statistics.median(x[0] for x in r)
        ob = f"{r[0][2]:.3f}" if r[0][2] is not None else "-"
        closure = f"{r[0][1]:.3f}" if r[0][1] is not None else "-"
        print(f"| {name} | {label} | {r[0][3]} | {closure} | {ob} | {wall:.2f} |")

    line("resolved (shipped)", a)
    line(f"line, lattice {LINE_SPACING} m", b)
    print(f"| {name} | ratio line / resolved (median of {repeats}) | | | | {ratio:.2f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--full-ring", action="store_true")
    ap.add_argument("--as-built", action="store_true")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-line-sink-")
    print("| project | pipes | particles | closure day | OB 60 d (m) | wall s |")
    print("|---|---|---|---|---|---|")
    pairs("single_ring_sand", {}, LINE, args.repeats, work)
    if args.full_ring:
        no_symmetry = {"numerics": {"symmetry": "none"}}
        pairs("single_ring_sand", no_symmetry, merged(LINE, no_symmetry), 1, work)
    if args.as_built:
        pairs("as_built_shaft", {}, LINE, 1, work)


if __name__ == "__main__":
    main()
