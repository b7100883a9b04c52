#!/usr/bin/env python3
"""What each lever bought: the single-ring sand case to 120 days, one
thread, CPU seconds (the machine is shared: CPU time of a single-threaded
run is far less disturbed by other load than wall time). Each row is a
choice of numerics with the current build, from the paper's method through
the integrators to graded spacing (the default); accuracy against
bench/converged.json. Levers that are code, not settings (the kernel's
loop, the set-up), are measured in bench/README.md from before/after runs.

  python3 bench/levers.py [--skip-implicit] [--old-exe PATH]   # PATH: a frostwall
                                            # built from an earlier commit, for "old" rows
"""
import argparse, json, os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

LEVERS = [
    ("paper mode: 2.5 cm lattice, explicit forward Euler, beta = 0.1", "new",
     {"integrator": "explicit", "beta": 0.1, "spacing": 0.025, "placement": "lattice"}),
    ("implicit backward Euler (Newton, BiCGSTAB + Jacobi), 2.5 cm lattice, step_change 0.25", "new",
     {"integrator": "implicit", "spacing": 0.025, "placement": "lattice", "step_change": 0.25}),
    ("RKL2, 2.5 cm lattice, step_change 0.25 (the default before)", "new",
     {"integrator": "rkl2", "spacing": 0.025, "placement": "lattice", "step_change": 0.25}),
    ("RKL2, 2.5 cm lattice, step_change 1", "new",
     {"integrator": "rkl2", "spacing": 0.025, "placement": "lattice", "step_change": 1.0}),
    ("graded 2 cm (wall band at 2 cm, far field 16 cm), RKL2, step_change 1: **the default**", "new", None),
    ("graded 1.8 cm, RKL2, step_change 1", "new", {"spacing": 0.018}),
    ("graded 1.5 cm, RKL2, step_change 1", "new", {"spacing": 0.015}),
]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--old-exe", default="")
    ap.add_argument("--extra", action="append", default=[], help="label=JSON numerics, added as a row")
    ap.add_argument("--skip-implicit", action="store_true", help="leave out the implicit row (about 5 minutes)")
    args = ap.parse_args()
    with open(bench.CONVERGED) as f:
        ref = json.load(f)
    work = tempfile.mkdtemp(prefix="frostwall-levers-")
    rows = list(LEVERS) + [(e.split("=", 1)[0], "new", json.loads(e.split("=", 1)[1])) for e in args.extra]
    print("| lever | particles | rate evaluations | CPU s (1 thread) | closure day | error | OB 60 d error | OB 100 d error |")
    print("|---|---|---|---|---|---|---|---|")
    for k, (label, which, numerics) in enumerate(rows):
        if args.skip_implicit and numerics and numerics.get("integrator") == "implicit":
            continue
        exe = args.old_exe if which == "old" else bench.EXE
        if not exe or not os.path.exists(exe):
            continue
        r = bench.facts(bench.run(numerics, 1, work, f"lever{k}", exe))
        print(f"| {label} | {r['particles']} | {r['evaluations']} | {r['cpu']:.1f} | {r['closure_day']:.3f} | "
              f"{100 * (r['closure_day'] - ref['closure_day']) / ref['closure_day']:+.2f} % | "
              f"{100 * (r['OB60'] - ref['OB60']):+.1f} cm | {100 * (r['OB100'] - ref['OB100']):+.1f} cm |", flush=True)


if __name__ == "__main__":
    main()
