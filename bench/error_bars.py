#!/usr/bin/env python3
"""How well the error estimate works: the shipped shafts run with
numerics.error_estimate at the default spacing and at eight more, each
closure day's error bar set against the converged closure day (the main
job 13.845 d, bench/README.md; the three-hole the independent solvers'
6.61 d; the four-hole the converged SPH 1.146 d: 1.1471 / 1.1473 / 1.1456 d
at 1.5 / 1.0 / 0.75 cm). Prints one row per run: spacing, closure, error
bar, true error, whether the bar covers it and whether it is at most 4
times it (or 0.05 d), then the counts. 1 thread; about 10 minutes.

  python3 bench/error_bars.py
"""
import json, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = [("single_ring_sand.json", 13.845, [0.017, 0.018, 0.019, 0.021, 0.022, 0.023, 0.024, 0.025]),
         ("three_hole_sand.json", 6.61, [0.017, 0.018, 0.019, 0.021, 0.022, 0.023, 0.024, 0.025]),
         ("four_hole_sand.json", 1.146, [0.013, 0.014, 0.0145, 0.016, 0.0165, 0.017, 0.018])]


def run(name, spacing, work):
    with open(os.path.join(ROOT, "projects", name)) as f:
        p = json.load(f)
    p.setdefault("numerics", {})["error_estimate"] = True
    if spacing:
        p["numerics"]["spacing"] = spacing
    out = tempfile.mkdtemp(dir=work)
    p["output"] = {"directory": out, "vtk": False, "full_ring": False, "report": False}
    path = os.path.join(out, "project.in.json")
    with open(path, "w") as f:
        json.dump(p, f)
    subprocess.run([bench.EXE, "--threads", "1", "run", path], check=True, capture_output=True,
                   env=dict(os.environ, CI="1"))
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    work = tempfile.mkdtemp(prefix="frostwall-error-bars-")
    covered = bounded = total = 0
    print("| project | spacing (m) | closure (d) | error bar (d) | true error (d) | covers | within 4x or 0.05 d |")
    print("|---|---|---|---|---|---|---|")
    for name, truth, spacings in CASES:
        for spacing in [None] + spacings:
            s = run(name, spacing, work)
            f, e = s["closure_time_days"], s["closure_time_days_error"]
            err = abs(f - truth)
            c, b = e >= err, e <= max(4 * err, 0.05)
            covered, bounded, total = covered + c, bounded + b, total + 1
            label = f"{s['run']['spacing']:.4f}" + (" (default)" if spacing is None else "")
            print(f"| {name[:-5]} | {label} | {f:.4f} | {e:.4f} | {err:.4f} | {'yes' if c else 'no'} | {'yes' if b else 'no'} |",
                  flush=True)
    print(f"\ncovered {covered} of {total}; within 4 times (or 0.05 d) {bounded} of {total}")


if __name__ == "__main__":
    main()
