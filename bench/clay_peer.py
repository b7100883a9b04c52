#!/usr/bin/env python3
"""The single ring in clay beside the finite-element peer: the closure day of
projects/single_ring_clay_power.json (pore water freezing along Anderson and
Tice's power law; closure = the first path of ground whose water is at least
half ice) and, with --step, of projects/single_ring_clay.json (isothermal
freezing; closure = the first fully frozen path), from `frostwall run` at a
few spacings and from the peer (bench/peer/clay_ring.edp, FreeFem++, 1/52
wedge, one core) at a few levels, in one script run, one after the other.

  python3 bench/clay_peer.py                          # power law: frostwall 3, 2, 1.5 cm; peer levels 1, 2, 3
  python3 bench/clay_peer.py --step                   # and the step-law clay
  python3 bench/clay_peer.py --levels 1 2 --spacings 0.03,0.02
  python3 bench/clay_peer.py --no-frostwall --levels 2 3 3.5
  python3 bench/clay_peer.py --exe other/build/app/frostwall   # another frostwall binary
  python3 bench/clay_peer.py --step --dt-check        # also the finest level at half its step

Frostwall runs a temporary copy of the project (end --days, no VTK, report
or error estimate, output in a temporary folder) on --threads threads
(OMP_NUM_THREADS set too) and its summary.json gives closure_time_days.

The peer's levels halve both the mesh size and the step from one level to
the next. Backward Euler is first order in the step and the closure day's
error in the mesh is no better than second order, so the limit assumed is
the first-order one, 2 d(finest) - d(next), with the order observed from the
three finest levels (p from (d1 - d0)/(d2 - d1) = 2^p) printed beside it and
the limit at that order. The uncertainty quoted is the larger of the last
level's correction |d(finest) - limit| and the two limits' spread.

The step and mesh errors can have opposite signs and cancel along the
levels (the power-law closure comes early on coarse meshes and late with
long steps), so the levels alone can look converged too soon. --dt-check
also runs the finest level at half its step: backward Euler's error there
is e = 2 (d(dt) - d(dt/2)) (first order), twice that at the level before. With both days so
corrected, the mesh limit is taken at second order (P1),
D(finest) + (D(finest) - D(before))/3, and its uncertainty is the spread to
the first-order mesh limit and to the levels' limit. The power-law closure
moves smoothly with the step (first order); the step law's fully frozen
closure waits for the last node of the neck to give up its latent heat and
moves with the step in jumps, so there --dt-check's correction is only an
indication (halve -dtf further by hand: FreeFem++-nw bench/peer/clay_ring.edp
-law step -level 2 -dtf 0.25). Install the peer with
`apt-get install -y freefem++`.
"""
import argparse, json, math, os, shutil, subprocess, sys, tempfile, time

from freefem import run_freefem

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
PEER = os.path.join(ROOT, "bench", "peer", "clay_ring.edp")
CASES = {"power": "single_ring_clay_power", "step": "single_ring_clay"}


def run_frostwall(exe, case, spacing, days, threads, work):
    """frostwall on a copy of the project at `spacing` to `days`: its summary,
    with the script's wall time added."""
    with open(os.path.join(ROOT, "projects", CASES[case] + ".json")) as f:
        p = json.load(f)
    out = os.path.join(work, f"fw_{case}_{spacing:g}")
    p["time"] = {"end": days, "unit": "d", "snapshots": [days]}
    p["output"] = {"directory": out, "vtk": False, "full_ring": False, "report": False}
    p.setdefault("numerics", {}).update({"spacing": spacing, "error_estimate": False})
    path = out + ".json"
    with open(path, "w") as f:
        json.dump(p, f)
    env = dict(os.environ, CI="1", OMP_NUM_THREADS=str(threads))
    start = time.perf_counter()
    proc = subprocess.run([exe, "--threads", str(threads), "run", path], capture_output=True, text=True, env=env)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        sys.exit(f"frostwall failed on {path}: {proc.stderr[-2000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    s["script_wall_s"] = wall
    return s


def run_peer(case, level, days, dtf, work):
    """The peer at `level`: its JSON, with the script's wall time added."""
    out = os.path.join(work, f"peer_{case}_L{level:g}_dtf{dtf:g}.json")
    return run_freefem(PEER, ["-law", case, "-level", f"{level:g}", "-dtf", f"{dtf:g}", "-days", f"{days:g}"], out,
                       work)


def limits(days):
    """From the peer's days at successive levels: (first-order limit, observed
    order or None, limit at the observed order or None, uncertainty)."""
    if len(days) < 2:
        return None, None, None, None
    d1, d2 = days[-2], days[-1]
    lim1 = 2.0 * d2 - d1
    p = limp = None
    if len(days) >= 3:
        a, b = days[-3] - days[-2], days[-2] - days[-1]
        if a * b > 0 and abs(b) > 0:
            p = math.log2(a / b)
            if p > 0.05:
                limp = d2 + (d2 - d1) / (2.0 ** p - 1.0)
    unc = abs(d2 - lim1)
    if limp is not None:
        unc = max(unc, abs(lim1 - limp))
    return lim1, p, limp, unc


def separated(d_before, d_fine, d_fine_half, lim_levels):
    """The mesh limit with the step's error taken out (see --dt-check):
    (limit, step error at the finest level, uncertainty)."""
    e = 2.0 * (d_fine - d_fine_half)
    D1, D0 = d_fine - e, d_before - 2.0 * e
    lim2 = D1 + (D1 - D0) / 3.0
    lim1 = D1 + (D1 - D0)
    unc = max(abs(lim1 - lim2), abs(lim_levels - lim2) if lim_levels is not None else 0.0)
    return lim2, e, unc


def fmt(d, nd=3):
    return "open" if d is None else f"{d:.{nd}f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--step", action="store_true", help="also the step-law clay (projects/single_ring_clay.json)")
    ap.add_argument("--only-step", action="store_true", help="the step-law clay alone")
    ap.add_argument("--spacings", default="0.03,0.02,0.015")
    ap.add_argument("--levels", type=float, nargs="*", default=[1.0, 2.0, 3.0])
    ap.add_argument("--dtf", type=float, default=1.0, help="the peer's step factor")
    ap.add_argument("--dt-check", action="store_true", help="also run the finest level at half its step")
    ap.add_argument("--days", type=float, default=20.0)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--exe", default=EXE)
    ap.add_argument("--no-peer", action="store_true")
    ap.add_argument("--no-frostwall", action="store_true")
    ap.add_argument("--keep", action="store_true", help="keep the work folder")
    args = ap.parse_args()
    if not args.no_peer and not shutil.which("FreeFem++-nw"):
        sys.exit("the peer needs FreeFem++: apt-get install -y freefem++ (or --no-peer)")
    cases = ["step"] if args.only_step else (["power", "step"] if args.step else ["power"])
    spacings = [float(s) for s in args.spacings.split(",") if s]
    work = tempfile.mkdtemp(prefix="frostwall-clay-peer-")
    for case in cases:
        print(f"\n## {CASES[case]} ({'power-law curve, closure at liquid fraction <= 0.5' if case == 'power' else 'isothermal freezing, closure fully frozen'})\n")
        peer = []
        if not args.no_peer:
            print("| peer level | vertices | dt h | accepted steps | Newton its | closure day | f<=0.5 day | f<=0.25 day | wall s |")
            print("|---|---|---|---|---|---|---|---|---|")
            for lv in args.levels:
                r = run_peer(case, lv, args.days, args.dtf, work)
                peer.append(r)
                print(f"| {lv:g} | {r['vertices']} | {r['dt_hours']:g} | {r['accepted_substeps']} | {r['newton_iterations']} | "
                      f"{fmt(r['closure_day'])} | {fmt(r['half_day'])} | {fmt(r['quarter_day'])} | {r['script_wall_s']:.0f} |",
                      flush=True)
        half = None
        if args.dt_check and peer:
            lv = args.levels[-1]
            half = run_peer(case, lv, args.days, 0.5 * args.dtf, work)
            print(f"| {lv:g}, half step | {half['vertices']} | {half['dt_hours']:g} | {half['accepted_substeps']} | "
                  f"{half['newton_iterations']} | {fmt(half['closure_day'])} | {fmt(half['half_day'])} | "
                  f"{fmt(half['quarter_day'])} | {half['script_wall_s']:.0f} |", flush=True)
        days = [r["closure_day"] for r in peer if r["closure_day"] is not None]
        lim1, p, limp, unc = limits(days)
        ref = None
        if lim1 is not None:
            ref = lim1
            line = f"\npeer limit (first order, 2 d(L{args.levels[-1]:g}) - d(L{args.levels[-2]:g})): {lim1:.3f} +- {unc:.3f} d"
            if p is not None:
                line += f"; observed order from the last three levels p = {p:.2f}"
                if limp is not None:
                    line += f", limit at that order {limp:.3f} d"
            else:
                line += "; observed order: - (fewer than three levels, or the differences change sign)"
            print(line)
            if half is not None and half["closure_day"] is not None and len(days) >= 2:
                lim, e, u = separated(days[-2], days[-1], half["closure_day"], lim1)
                print(f"step error at level {args.levels[-1]:g}: {e:+.4f} d (first order); with it taken out, the mesh "
                      f"limit (second order) {lim:.3f} +- {u:.3f} d: the reference below")
                ref = lim
        elif days:
            ref = days[-1]
            print(f"\npeer: one level only, its day {ref:.3f} is the reference (no extrapolation)")
        if not args.no_frostwall:
            print("\n| frostwall spacing (m) | particles | closure day | vs peer limit | wall s |")
            print("|---|---|---|---|---|")
            for h in spacings:
                s = run_frostwall(args.exe, case, h, args.days, args.threads, work)
                d = s.get("closure_time_days")
                rel = "-" if (d is None or ref is None) else f"{100.0 * (d - ref) / ref:+.2f} %"
                print(f"| {h:g} | {s['run'].get('particles', '-')} | {fmt(d)} | {rel} | {s['script_wall_s']:.0f} |", flush=True)
        print(f"\n(frostwall on {args.threads} threads; the peer on one core; work folder {work})")
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
