#!/usr/bin/env python3
"""The seepage run's speed target: the single ring in sand at 1 m/d of seepage against
still water, CPU seconds on one thread over the first `--days` (0.5 by default:
the full 120 days under seepage take more than an hour). Four rows in one script
run: still water on its wedge (the product's run), still water on the full ring
(numerics.symmetry off: the cloud the flow needs is half of it), and the
seepage run on its half section with the default coupled step and with the
explicit limited scheme (held to the advective Courant limit). The ratios
compare the same simulated days (set-up included).

  python3 bench/seepage_rate.py [--days 0.5]
  python3 bench/seepage_rate.py --reference [--flux 0.5] [--days 120]

--reference: projects/seepage_reference.json (the finite-element model's
settings) to day 120 on 2 threads, beside the still-water main job on 2
threads in the same script run; prints the wall times, their ratio, and
closure per gap and the axis walls against the finite-element values.
"""
import argparse, json, math, os, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

WATER = {"groundwater": {"hydraulic_conductivity": 1e-4, "porosity": 0.35, "darcy_flux": [1.0, 0.0], "unit": "m/d"}}


FE = {"still water closure (d)": 13.86, "0.5 m/d closure (d)": 65.6, "0.5 m/d flank gap at 76 deg (d)": 13.6,
      "1 m/d upstream axis wall, half-frozen, pipe included (m)": 0.47}


def timed(path, threads=2):
    start = time.perf_counter()
    subprocess.run([bench.EXE, "--threads", str(threads), "run", path], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=dict(os.environ, CI="1"))
    return time.perf_counter() - start


def reference(flux, days):
    work = tempfile.mkdtemp(prefix="frostwall-seepage-ref-")
    with open(os.path.join(bench.ROOT, "projects", "seepage_reference.json")) as f:
        p = json.load(f)
    p["groundwater"]["darcy_flux"] = [flux, 0.0]
    p["time"] = {"end": days, "unit": "d", "snapshots": [d for d in (20, 40, 60, 80, 100, 120) if d < days] + [days]}
    p["output"] = {"directory": os.path.join(work, "out"), "vtk": False, "full_ring": False, "report": False}
    path = os.path.join(work, "reference.json")
    with open(path, "w") as f:
        json.dump(p, f)
    with open(bench.CASE) as f:
        main_job = json.load(f)
    main_job["output"]["directory"] = os.path.join(work, "main")
    main_path = os.path.join(work, "main.json")
    with open(main_path, "w") as f:
        json.dump(main_job, f)
    still = timed(main_path)
    wall = timed(path)
    s = json.load(open(os.path.join(work, "out", "summary.json")))
    g = s["groundwater"]
    print(f"main job (still water, 2 threads): {still:.1f} s; seepage reference at {flux:g} m/d to day {days:g}: "
          f"{wall:.1f} s = {wall / still:.0f} x; {s['run']['particles']} particles, {s['run']['steps']} steps, "
          f"{s['run']['newton_iterations']} Newton iterations, {g['flow_solves']} flow solves")
    print(f"closure {s['closure_time_days']} d; {g['verdict']}")
    print("| gap | angle of its middle (deg) | side | closure (d) |\n|---|---|---|---|")
    for gap in g["gaps"]:
        angle = math.degrees(math.atan2(gap["middle"][1], gap["middle"][0]))
        day = gap["closure_day"]
        print(f"| {gap['between']} | {angle:.0f} | {gap['position']} | {'open' if day is None else f'{day:.2f}'} |")
    print("| day | upstream axis wall OB (m) | downstream axis wall OA (m) |\n|---|---|---|")
    for w in s["wall"]:
        print(f"| {w['day']:g} | {w['OB']['thickness']:.3f} | {w['OA']['thickness']:.3f} |")
    print("finite-element reference:", FE)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--days", type=float, default=None)
    ap.add_argument("--reference", action="store_true")
    ap.add_argument("--flux", type=float, default=0.5)
    args = ap.parse_args()
    if args.reference:
        return reference(args.flux, args.days or 120.0)
    args.days = args.days or 0.5
    work = tempfile.mkdtemp(prefix="frostwall-seepage-")
    span = {"end": args.days, "unit": "d", "snapshots": [args.days]}
    rows = [("still water, wedge (the product's run)", None, None),
            ("still water, full ring (symmetry off)", {"symmetry": "off"}, None),
            ("1 m/d, half section, coupled step (default)", None, WATER),
            ("1 m/d, half section, explicit limited", None,
             {"groundwater": dict(WATER["groundwater"], advection="limited")})]
    print(f"| run (first {args.days:g} d, 1 thread) | particles | steps | flow solves | CPU s | ratio to the wedge | ratio to the full ring |")
    print("|---|---|---|---|---|---|---|")
    first = ring = None
    for k, (label, numerics, extra) in enumerate(rows):
        r = bench.run(numerics, 1, work, f"seepage{k}", time_settings=span, extra=extra)
        s = r["summary"]
        first = first or r["cpu"]
        ring = r["cpu"] if k == 1 else ring
        solves = s.get("groundwater", {}).get("flow_solves", "")
        to_ring = f"{r['cpu'] / ring:.2f}" if ring else ""
        print(f"| {label} | {s['run']['particles']} | {s['run']['steps']} | {solves} | {r['cpu']:.1f} | {r['cpu'] / first:.0f} | {to_ring} |",
              flush=True)


if __name__ == "__main__":
    main()
