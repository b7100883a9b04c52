#!/usr/bin/env python3
"""frostwall benchmark: the single-ring sand case to 120 days.

  paper mode    uniform 2.5 cm lattice, explicit forward Euler, beta = 0.1
                (the SPH paper's method; pipes as discs as everywhere else)
  default mode  whatever frostwall ships as default (no numerics given)

Both run in this one invocation, back to back (paper then default, on 2 and on
1 thread, three times by default: the wall times are medians, and the ratio
is the median of the back-to-back pairs' ratios, since this shared machine's
speed drifts), with the same output settings (summary and CSV only: VTK
writing is disk speed, not the engine).
Accuracy is judged against the converged run stored in bench/converged.json
(made once with --converged; its settings are stored with it). Also: the
default mode on 1 and 2 OpenMP threads, and the kernel's pair-update rate
(build/bench/kernel_rate). Usage, from the repository root after set-up:

  python3 bench/bench.py                 # everything (about 6 minutes here)
  python3 bench/bench.py --repeats 1     # one run each (about 2 minutes)
  python3 bench/bench.py --converged     # (re)make bench/converged.json
  python3 bench/bench.py --converged-closure  # only its closure and contact days (to day 16)
  python3 bench/bench.py --convergence   # the default mode's closure day as the spacing is refined

Closure is the first fully frozen path (project-format.md); the independent
solvers (P1 finite elements and vertex-centred finite volumes,
converged) put it at 13.85 d for this case (INDEPENDENT_CLOSURE below).
"""
import argparse, copy, json, os, statistics, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
KERNEL = os.path.join(ROOT, "build", "bench", "kernel_rate")
CASE = os.path.join(ROOT, "projects", "single_ring_sand.json")
CONVERGED = os.path.join(ROOT, "bench", "converged.json")

PAPER = {"integrator": "explicit", "beta": 0.1, "spacing": 0.025, "placement": "lattice"}
CONVERGED_NUMERICS = {"integrator": "rkl2", "spacing": 0.0125, "step_change": 0.05, "placement": "lattice"}
INDEPENDENT_CLOSURE = 13.85  # d: P1 FE and vertex-centred FV enthalpy models, converged (tests/test_shaft_section.cpp)
CONVERGENCE_SPACINGS = [0.04, 0.03, 0.02, 0.015, 0.01, 0.007]


def run(numerics, threads, workdir, name, exe=EXE, time_settings=None, extra=None):
    """Runs the case with `numerics` (None: defaults) and the top-level blocks of `extra`
    set; returns summary, peak RSS, wall and CPU time."""
    with open(CASE) as f:
        project = json.load(f)
    project.update(extra or {})
    if time_settings is not None:
        project["time"] = time_settings
    if numerics is None:
        project.pop("numerics", None)
    else:
        project["numerics"] = numerics
    out = os.path.join(workdir, name)
    project["output"] = {"directory": out, "vtk": False, "full_ring": False, "report": False}
    path = os.path.join(workdir, name + ".json")
    with open(path, "w") as f:
        json.dump(project, f)
    start = time.perf_counter()
    proc = subprocess.Popen([exe, "--threads", str(threads), "run", path],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=dict(os.environ, CI="1"))
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    err = proc.stderr.read().decode()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"bench: run {name} failed: {err}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    return {"summary": summary, "peak_mb": usage.ru_maxrss / 1024.0, "wall": wall,
            "cpu": usage.ru_utime + usage.ru_stime}


def facts(r):
    s = r["summary"]
    ob = {round(w["day"]): w["OB"]["thickness"] for w in s["wall"]}
    run_ = s["run"]
    evaluations = run_["steps"] + run_.get("stages", 0) if run_["integrator"] == "rkl2" else run_["steps"]
    return {"particles": run_["particles"], "pairs": run_["pairs"], "steps": run_["steps"],
            "evaluations": evaluations, "integrator": run_["integrator"], "spacing": run_["spacing"],
            "closure_day": s["closure_time_days"], "contact_day": s.get("front_contact_days"),
            "OB60": ob.get(60), "OB100": ob.get(100),
            "wall": r["wall"], "cpu": r["cpu"], "peak_mb": r["peak_mb"],
            "pair_updates_per_s": evaluations * run_["pairs"] / r["wall"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--converged", action="store_true", help="make bench/converged.json (slow) and stop")
    ap.add_argument("--repeats", type=int, default=3, help="interleaved runs per mode and thread count (default 3)")
    ap.add_argument("--converged-closure", action="store_true",
                    help="remeasure only the converged run's closure and contact days (to day 16) and stop")
    ap.add_argument("--convergence", action="store_true",
                    help="the default mode's closure day at refined spacings (the main job, 120 days) and stop")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-bench-")

    if args.converged_closure:
        # Closure happens before day 16; the step limit of the run's time
        # curves (end / 200) is the 120-day run's, so its output rows are kept.
        with open(CONVERGED) as f:
            stored = json.load(f)
        short = {"end": 16, "unit": "d", "snapshots": [16]}
        start = time.perf_counter()
        numerics = dict(CONVERGED_NUMERICS)
        r = facts(run(numerics, 2, work, "converged_closure", time_settings=short))
        stored.update({"closure_day": r["closure_day"], "contact_day": r["contact_day"],
                       "closure_definition": "first fully frozen path (liquid fraction 0); contact: 0.5",
                       "closure_made": time.strftime("%Y-%m-%d"),
                       "closure_command": "python3 bench/bench.py --converged-closure",
                       "closure_wall_seconds": round(time.perf_counter() - start, 1)})
        with open(CONVERGED, "w") as f:
            json.dump(stored, f, indent=2)
            f.write("\n")
        print(json.dumps(stored, indent=2))
        return

    if args.convergence:
        print(f"default mode (graded, RKL2), single ring in sand to 120 days, {os.cpu_count()} threads; "
              f"independent solvers: closure {INDEPENDENT_CLOSURE} d\n")
        print("| spacing | particles | steps | closure day | vs 13.85 d | columns touch | OB 60 d | OB 100 d | wall s |")
        print("|---|---|---|---|---|---|---|---|---|")
        for spacing in CONVERGENCE_SPACINGS:
            r = facts(run({"spacing": spacing}, os.cpu_count() or 1, work, f"conv_{spacing}"))
            print(f"| {spacing} | {r['particles']} | {r['steps']} | {r['closure_day']:.3f} | "
                  f"{100 * (r['closure_day'] / INDEPENDENT_CLOSURE - 1):+.2f} % | {r['contact_day']:.3f} | "
                  f"{r['OB60']:.3f} m | {r['OB100']:.3f} m | {r['wall']:.1f} |", flush=True)
        return

    if args.converged:
        r = facts(run(CONVERGED_NUMERICS, 1, work, "converged"))  # results do not depend on threads
        stored = {"numerics": CONVERGED_NUMERICS, "closure_day": r["closure_day"], "OB60": r["OB60"],
                  "OB100": r["OB100"], "particles": r["particles"], "steps": r["steps"],
                  "wall_seconds": round(r["wall"], 1),
                  "made": time.strftime("%Y-%m-%d"), "command": "python3 bench/bench.py --converged"}
        with open(CONVERGED, "w") as f:
            json.dump(stored, f, indent=2)
            f.write("\n")
        print(json.dumps(stored, indent=2))
        return

    with open(CONVERGED) as f:
        ref = json.load(f)
    threads = os.cpu_count() or 1
    thread_counts = [threads] if threads == 1 else [threads, 1]
    modes = [("paper", PAPER), ("default", None)]
    # Interleaved repeats: paper then default, on each thread count, N times.
    # This machine is shared and its speed drifts from minute to minute, so a
    # ratio is taken within each back-to-back pair and the median reported.
    walls = {(name, t): [] for name, _ in modes for t in thread_counts}
    results = {}
    for r in range(args.repeats):
        for t in thread_counts:
            for name, numerics in modes:
                res = facts(run(numerics, t, work, f"{name}_t{t}_r{r}"))
                walls[(name, t)].append(res["wall"])
                if t == threads and name not in results:
                    results[name] = res
    for name, _ in modes:
        results[name]["wall"] = statistics.median(walls[(name, threads)])
        results[name]["pair_updates_per_s"] = (results[name]["evaluations"] * results[name]["pairs"] /
                                               results[name]["wall"])

    def err_day(x):
        return 100.0 * (x - ref["closure_day"]) / ref["closure_day"] if x is not None else float("nan")

    def err_cm(x, key):
        return 100.0 * (x - ref[key]) if x is not None else float("nan")

    print(f"frostwall bench: single ring, sand, 120 days, {threads} threads; converged reference "
          f"(spacing {ref['numerics']['spacing']} m, {ref['numerics']['integrator']}): closure {ref['closure_day']:.3f} d, "
          f"OB {ref['OB60']:.3f} m @60 d, {ref['OB100']:.3f} m @100 d; independent solvers: closure "
          f"{INDEPENDENT_CLOSURE} d; wall times are medians of {args.repeats} interleaved runs\n")
    head = ("| mode | integrator | spacing | particles | steps | rate evaluations | wall s | closure day | error | "
            "vs 13.85 d | OB 60 d | error | OB 100 d | error | pair-updates/s | peak MB |")
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for name, r in results.items():
        print(f"| {name} | {r['integrator']} | {r['spacing']:.4g} | {r['particles']} | {r['steps']} | {r['evaluations']} | "
              f"{r['wall']:.1f} | {r['closure_day']:.3f} | {err_day(r['closure_day']):+.2f} % | "
              f"{100 * (r['closure_day'] / INDEPENDENT_CLOSURE - 1):+.2f} % | "
              f"{r['OB60']:.3f} m | {err_cm(r['OB60'], 'OB60'):+.1f} cm | {r['OB100']:.3f} m | "
              f"{err_cm(r['OB100'], 'OB100'):+.1f} cm | {r['pair_updates_per_s']:.2e} | {r['peak_mb']:.0f} |")
    print()
    for t in thread_counts:
        ratios = [p / d for p, d in zip(walls[("paper", t)], walls[("default", t)])]
        print(f"wall-time ratio paper / default, {t} thread{'s' if t > 1 else ''}: "
              f"{statistics.median(ratios):.1f}x (median; pairs {', '.join(f'{x:.1f}' for x in ratios)}; "
              f"paper {', '.join(f'{x:.1f}' for x in walls[('paper', t)])} s, "
              f"default {', '.join(f'{x:.2f}' for x in walls[('default', t)])} s)")
    if len(thread_counts) > 1:
        for name, _ in modes:
            one, many = statistics.median(walls[(name, 1)]), statistics.median(walls[(name, threads)])
            print(f"OpenMP scaling, {name} mode: 1 thread {one:.2f} s, {threads} threads {many:.2f} s, "
                  f"speed-up {one / many:.2f}x")
    if os.path.exists(KERNEL):
        print("\nkernel (build/bench/kernel_rate):")
        sys.stdout.flush()
        subprocess.run([KERNEL], check=True)


if __name__ == "__main__":
    main()
