#!/usr/bin/env python3
"""Seepage side by side with the finite-element peer: projects/seepage_reference.json
(the single ring in sand, half section, 0.5 m/d) through `frostwall run` and the
peer (../shared/peer/seepage_ring.edp, FreeFem++, one core) in one script run,
one after the other. Prints both wall times and the per-gap closure table:
each gap's closure day from frostwall and from each peer level, and its
distance from the converged peer values (bench/peer_converged.json).

  python3 bench/seepage_peer.py                      # to day 90, peer level 1
  python3 bench/seepage_peer.py --days 60 --levels 0 1
  python3 bench/seepage_peer.py --spacing 0.03 --numerics '{"step_change": 0.5}'
  python3 bench/seepage_peer.py --no-peer            # frostwall only
  python3 bench/seepage_peer.py --converge           # remake bench/peer_converged.json

Install the peer with `apt-get install -y freefem++`. --converge runs the peer
at levels 1 and 1.5 to day 60 (about 15 minutes on one core) and stores, per
gap, both days and their limit: each level halves the step (backward Euler,
first order) and shrinks the mesh by sqrt 2 (P1, second order), so both
errors halve from level to level and the limit is 2 d(1.5) - d(1).
"""
import argparse, json, math, os, shutil, subprocess, sys, tempfile, time

from freefem import run_freefem

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
CASE = os.path.join(ROOT, "projects", "seepage_reference.json")
PEER = os.path.normpath(os.path.join(ROOT, "..", "shared", "peer", "seepage_ring.edp"))
CONVERGED = os.path.join(ROOT, "bench", "peer_converged.json")
PIPES = 26


def run_peer(level, days, flux, work):
    """The peer at `level` to `days`: its JSON, with the script's wall time added."""
    out = os.path.join(work, f"peer_L{level:g}_d{days:g}.json")
    os.makedirs(os.path.join(work, "runs"), exist_ok=True)
    return run_freefem(PEER, ["-level", f"{level:g}", "-q", f"{flux:g}", "-days", f"{days:g}"], out, work)


def peer_days(r):
    """Gap index -> fully frozen closure day (None while open)."""
    return {g["gap"]: g["day"] for g in r["closure_full"]}


def run_frostwall(days, flux, threads, spacing, numerics, work):
    with open(CASE) as f:
        p = json.load(f)
    p["groundwater"]["darcy_flux"] = [flux, 0.0]
    p["time"] = {"end": days, "unit": "d", "snapshots": [days]}
    p["output"] = {"directory": os.path.join(work, "fw"), "vtk": False, "full_ring": False, "report": False}
    p["numerics"] = dict(p.get("numerics", {}), **numerics)
    if spacing:
        p["numerics"]["spacing"] = spacing
    path = os.path.join(work, "frostwall.json")
    with open(path, "w") as f:
        json.dump(p, f)
    check = subprocess.run([EXE, "check", path], check=True, capture_output=True, text=True).stdout
    estimate = next((l.strip() for l in check.splitlines() if "run time:" in l), "run time: -")
    start = time.perf_counter()
    subprocess.run([EXE, "--threads", str(threads), "run", path], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, env=dict(os.environ, CI="1"))
    wall = time.perf_counter() - start
    with open(os.path.join(work, "fw", "summary.json")) as f:
        s = json.load(f)
    s["script_wall_s"] = wall
    s["check_estimate"] = estimate
    return s


def frostwall_days(s):
    """Gap index (the peer's numbering: gap k between the pipes at k and k+1
    times 360/26 degrees) -> closure day."""
    out = {}
    for g in s["groundwater"]["gaps"]:
        angle = math.degrees(math.atan2(g["middle"][1], g["middle"][0])) % 360.0
        k = round(angle / (360.0 / PIPES) - 0.5)
        out[k] = g["closure_day"]
    return out


def extrapolate(coarse, fine):
    """The limit of the peer's closure day from two levels: each level halves the
    step (backward Euler, first order) and shrinks the mesh by sqrt 2 (P1,
    second order), so both errors halve and the limit is 2 fine - coarse."""
    return 2.0 * fine - coarse


def converge(flux, work, levels):
    runs = {lv: run_peer(lv, 60, flux, work) for lv in levels}
    gaps = {}
    for k in range(PIPES // 2):
        d = [peer_days(runs[lv]).get(k) for lv in levels]
        if None in d:
            continue
        gaps[str(k)] = dict({"angle_deg": (k + 0.5) * 360 / PIPES},
                            **{f"level_{lv:g}": v for lv, v in zip(levels, d)},
                            extrapolated=extrapolate(d[-2], d[-1]))
    result = {"flux_m_per_day": flux, "days": 60, "levels": levels,
              "command": "python3 bench/seepage_peer.py --converge " + " ".join(f"{lv:g}" for lv in levels),
              "wall_s": {f"level_{lv:g}": runs[lv]["script_wall_s"] for lv in runs}, "gaps": gaps}
    with open(CONVERGED, "w") as f:
        json.dump(result, f, indent=1)
    print(json.dumps(result, indent=1))


def reference_days():
    """Gap -> the converged peer day (extrapolated from its two finest levels)."""
    if not os.path.exists(CONVERGED):
        return {}
    with open(CONVERGED) as f:
        c = json.load(f)
    return {int(k): g["extrapolated"] for k, g in c["gaps"].items()}


def fmt_day(d):
    return "open" if d is None else f"{d:.2f}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--days", type=float, default=90.0)
    ap.add_argument("--flux", type=float, default=0.5)
    ap.add_argument("--levels", type=float, nargs="*", default=[1.0])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--spacing", type=float, default=None)
    ap.add_argument("--numerics", default="{}", help="JSON merged into the project's numerics")
    ap.add_argument("--no-peer", action="store_true")
    ap.add_argument("--no-frostwall", action="store_true")
    ap.add_argument("--converge", type=float, nargs="*", default=None,
                    help="remake bench/peer_converged.json from these peer levels (default 1 1.5)")
    ap.add_argument("--keep", action="store_true", help="keep the work folder")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-peer-")
    if args.converge is not None:
        return converge(args.flux, work, args.converge or [1.0, 1.5])
    if not args.no_peer and not shutil.which("FreeFem++-nw"):
        sys.exit("the peer needs FreeFem++: apt-get install -y freefem++ (or --no-peer)")
    columns, times = [], []
    if not args.no_frostwall:
        s = run_frostwall(args.days, args.flux, args.threads, args.spacing, json.loads(args.numerics), work)
        r = s["run"]
        label = f"frostwall ({r['particles']} particles)"
        columns.append((label, frostwall_days(s)))
        times.append(f"{label}: {s['script_wall_s']:.1f} s wall on {args.threads} threads, {r['steps']} steps, "
                     f"{r.get('newton_iterations', '-')} Newton iterations, {s['groundwater']['flow_solves']} flow "
                     f"solves; ring closed on day {s['closure_time_days']}")
        times.append(f"frostwall check beforehand: {s['check_estimate']}")
    if not args.no_peer:
        for lv in args.levels:
            p = run_peer(lv, args.days, args.flux, work)
            label = f"peer level {lv:g} ({p['vertices']} vertices)"
            columns.append((label, peer_days(p)))
            times.append(f"{label}: {p['script_wall_s']:.1f} s wall on 1 core ({p['wall_solve_s']:.1f} s solve), "
                         f"{p['accepted_substeps']} steps, {p['newton_iterations']} Newton iterations")
    ref = reference_days()
    print(f"seepage reference at {args.flux:g} m/d to day {args.days:g}")
    for t in times:
        print(" ", t)
    head = "| gap | angle (deg) | " + " | ".join(c[0] for c in columns)
    head += " | converged peer | " + " | ".join(f"{c[0].split(' (')[0]} error" for c in columns) + " |"
    print(head)
    print("|" + "---|" * (3 + 2 * len(columns)))
    worst = [0.0] * len(columns)
    for k in range(PIPES // 2):
        days = [c[1].get(k) for c in columns]
        ref_k = ref.get(k)
        errors = []
        for i, d in enumerate(days):
            if ref_k is None or d is None:
                errors.append("-")
                continue
            e = (d - ref_k) / ref_k
            worst[i] = max(worst[i], abs(e))
            errors.append(f"{100 * e:+.1f} %")
        print(f"| {k} | {(k + 0.5) * 360 / PIPES:.1f} | " + " | ".join(fmt_day(d) for d in days) +
              f" | {fmt_day(ref_k)} | " + " | ".join(errors) + " |")
    if ref:
        print("largest per-gap error against the converged peer (gaps it closes by day 60): " +
              ", ".join(f"{c[0].split(' (')[0]} {100 * w:.1f} %" for c, w in zip(columns, worst)))
    finish(work, args.keep)


def finish(work, keep):
    """Keeps the work folder (and says where) or removes it."""
    if keep:
        print("work folder:", work)
    else:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
