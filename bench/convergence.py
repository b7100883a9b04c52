#!/usr/bin/env python3
"""Convergence of the shipped shafts in the spacing.

  python3 bench/convergence.py                 # single ring, three-hole, four-hole at 3, 2.5, 2, 1.5, 1 cm
  python3 bench/convergence.py --spacings 0.03,0.02  --projects single_ring_sand
  python3 bench/convergence.py --model line --placement lattice --spacings 0.08,0.06,0.05,0.04,0.03

Each project runs to its own end (120 days) with only numerics.spacing
changed (and pipe.model and numerics.placement when given), without VTK,
report or error estimate, on all cores. Prints one markdown table per
project (closure day, OA and OB thickness at 60 days, free particles, wall
seconds) and the observed order of the closure day and of the OB thickness
from each three successive spacings ('-' where the two differences change
sign).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
PROJECTS = ["single_ring_sand", "three_hole_sand", "four_hole_sand"]
SPACINGS = [0.03, 0.025, 0.02, 0.015, 0.01]
REFERENCES = {"single_ring_sand": (13.845, 0.004), "three_hole_sand": (6.612, 0.037),
              "four_hole_sand": (1.1436, 0.0095)}


def run_project(project, out, threads, exe=EXE):
    """Writes `project` beside `out` (its output directory), runs it and
    returns the wall seconds and its summary.json."""
    path = out + ".json"
    with open(path, "w") as f:
        json.dump(project, f)
    start = time.perf_counter()
    proc = subprocess.run([exe, "--threads", str(threads), "run", path], capture_output=True, text=True,
                          env=dict(os.environ, CI="1"))
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        sys.exit(f"{project.get('name')} ({out}) failed: {proc.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        return wall, json.load(f)


def run(name, spacing, work, threads, exe=EXE, model=None, placement=None):
    with open(os.path.join(ROOT, "projects", name + ".json")) as f:
        project = json.load(f)
    project.setdefault("numerics", {})
    project["numerics"].update({"spacing": spacing, "error_estimate": False})
    if model:
        project["pipe"]["model"] = model
    if placement:
        project["numerics"]["placement"] = placement
    out = os.path.join(work, f"{name}_{spacing}_{model}_{placement}")
    project["output"] = {"directory": out, "vtk": False, "full_ring": False, "report": False}
    wall, s = run_project(project, out, threads, exe)
    ob60 = next((w["OB"]["thickness"] for w in s["wall"] if round(w["day"]) == 60), None)
    oa60 = next((w["OA"]["thickness"] for w in s["wall"] if round(w["day"]) == 60), None)
    return {"closure": s["closure_time_days"], "ob60": ob60, "oa60": oa60, "particles": s["run"]["particles"],
            "wall": wall}


def observed_order(h, c):
    """The order p from each three successive spacings h1 > h2 > h3: the p with
    (c1 - c2) / (c2 - c3) = (h1^p - h2^p) / (h2^p - h3^p) (bisection on
    0.05..8); None where the differences change sign or no p fits."""
    orders = []
    for k in range(len(c) - 2):
        d1, d2 = c[k] - c[k + 1], c[k + 1] - c[k + 2]
        if d1 * d2 <= 0:
            orders.append(None)
            continue
        target = d1 / d2

        def ratio(p):
            return (h[k] ** p - h[k + 1] ** p) / (h[k + 1] ** p - h[k + 2] ** p)

        lo, hi = 0.05, 8.0
        if not (ratio(lo) - target) * (ratio(hi) - target) < 0:
            orders.append(None)
            continue
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if (ratio(lo) - target) * (ratio(mid) - target) <= 0:
                hi = mid
            else:
                lo = mid
        orders.append(0.5 * (lo + hi))
    return orders


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--projects", default=",".join(PROJECTS))
    ap.add_argument("--spacings", default=",".join(str(s) for s in SPACINGS))
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--exe", default=EXE, help="the frostwall program (default: build/app/frostwall)")
    ap.add_argument("--model", help="pipe.model (default: the project's)")
    ap.add_argument("--placement", help="numerics.placement (default: the project's)")
    args = ap.parse_args()
    spacings = [float(s) for s in args.spacings.split(",")]
    work = tempfile.mkdtemp(prefix="frostwall-convergence-")
    for name in args.projects.split(","):
        ref, u = REFERENCES.get(name, (None, None))
        print(f"\n{name} (reference {ref} +- {u} d)\n")
        print("| spacing (m) | free particles | closure day | vs reference | OA 60 d (m) | OB 60 d (m) | wall s |")
        print("|---|---|---|---|---|---|---|")
        closures, obs = [], []
        for h in spacings:
            r = run(name, h, work, args.threads, args.exe, args.model, args.placement)
            closures.append(r["closure"])
            obs.append(r["ob60"])
            vs = f"{100 * (r['closure'] / ref - 1):+.2f} %" if ref else ""
            oa = f"{r['oa60']:.3f}" if r["oa60"] is not None else "-"
            ob = f"{r['ob60']:.3f}" if r["ob60"] is not None else "-"
            print(f"| {h} | {r['particles']} | {r['closure']:.4f} | {vs} | {oa} | {ob} | {r['wall']:.1f} |", flush=True)

        def orders_text(values):
            if any(v is None for v in values):
                return "-"
            return ", ".join("-" if p is None else f"{p:.2f}" for p in observed_order(spacings, values))
        print("\nobserved order (successive triples): closure day " + orders_text(closures) + "; OB thickness " +
              orders_text(obs))


if __name__ == "__main__":
    main()
