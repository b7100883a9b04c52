#!/usr/bin/env python3
"""The shaft as built: what sections cost, in one script run.

  python3 bench/as_built.py ranks      # sections over MPI ranks against one rank
  python3 bench/as_built.py ring       # the full 26-pipe ring without symmetry against the wedge
  python3 bench/as_built.py shipped    # projects/as_built_shaft.json as shipped

ranks: projects/as_built_shaft.json at --spacing (default 0.04) with
sections at --depths (default 30 60), run in turn --rounds times each:
one rank (sections side by side, one thread each: the default), one rank
with --jobs 1 (one section at a time on every thread), and
`mpirun -np 2` (a section per rank). Prints the wall times, their medians,
the ratios to one rank, and whether the two-rank summary equals the
one-rank summary (wall times and thread counts aside).

ring: the main job (projects/single_ring_sand.json, default accuracy) on
its symmetry wedge and on the full ring placed without symmetry
("numerics": {"symmetry": "none"}, what an as-built section runs), in turn.
"""
import argparse, json, os, shutil, statistics, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"]


def timed(cmd, cwd):
    start = time.perf_counter()
    subprocess.run(cmd, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def summary(path):
    with open(path) as f:
        s = json.load(f)
    for k in ("wall_seconds", "threads"):
        s.get("run", {}).pop(k, None)
    return s


def write_project(work, name, patch):
    with open(os.path.join(ROOT, "projects", "as_built_shaft.json")) as f:
        p = json.load(f)
    p.update(patch)
    p["survey"]["file"] = os.path.join(ROOT, "projects", "as_built_survey.csv")
    p["output"]["directory"] = os.path.join(work, name + "_out")
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(p, f, indent=1)
    return path


def ranks(args, work):
    project = write_project(work, "ranks", {"numerics": {"spacing": args.spacing}, "sections": {"depths": args.depths}})
    out = os.path.join(work, "ranks_out")
    ways = {"1 rank": [EXE, "run", project], "1 rank, --jobs 1": [EXE, "run", "--jobs", "1", project],
            "2 ranks": MPIRUN + [EXE, "run", project]}
    times = {k: [] for k in ways}
    same = None
    for r in range(args.rounds):
        for name, cmd in ways.items():
            shutil.rmtree(out, ignore_errors=True)
            times[name].append(timed(cmd, work))
            if name == "1 rank":
                one = summary(os.path.join(out, "summary.json"))
            if name == "2 ranks":
                same = (same is not False) and summary(os.path.join(out, "summary.json")) == one
        print(f"round {r + 1}: " + ", ".join(f"{k} {v[-1]:.1f} s" for k, v in times.items()), flush=True)
    base = statistics.median(times["1 rank"])
    for name, t in times.items():
        m = statistics.median(t)
        ratios = [a / b for a, b in zip(t, times["1 rank"])]
        print(f"{name:18s} median {m:7.1f} s   ratio to 1 rank: median {statistics.median(ratios):.2f} "
              f"(pairs {', '.join(f'{x:.2f}' for x in ratios)})")
    print(f"2-rank summary equals the 1-rank summary: {same}")


def ring(args, work):
    with open(os.path.join(ROOT, "projects", "single_ring_sand.json")) as f:
        base = json.load(f)
    paths = {}
    for name, numerics in (("wedge", {}), ("full ring, no symmetry", {"symmetry": "none"})):
        p = json.loads(json.dumps(base))
        p["numerics"] = numerics
        p["output"] = {"directory": os.path.join(work, name.replace(" ", "_").replace(",", "")), "vtk": True,
                       "report": False}
        paths[name] = os.path.join(work, name.replace(" ", "_").replace(",", "") + ".json")
        with open(paths[name], "w") as f:
            json.dump(p, f)
    times = {k: [] for k in paths}
    for r in range(args.rounds):
        for name, path in paths.items():
            times[name].append(timed([EXE, "run", path], work))
        print(f"round {r + 1}: " + ", ".join(f"{k} {v[-1]:.1f} s" for k, v in times.items()), flush=True)
    for name, path in paths.items():
        s = summary(os.path.join(work, name.replace(" ", "_").replace(",", ""), "summary.json"))
        print(f"{name:24s} median {statistics.median(times[name]):6.1f} s, {s['run']['particles']} particles, "
              f"{s['run']['stages']} stages, closure {s['closure_time_days']:.3f} d, "
              f"thinnest wall {s['wall'][-1]['min_thickness']:.3f} m")
    r = [a / b for a, b in zip(times["full ring, no symmetry"], times["wedge"])]
    print(f"full ring / wedge: median {statistics.median(r):.1f}")


def shipped(args, work):
    t = timed([EXE, "run", os.path.join(ROOT, "projects", "as_built_shaft.json")], ROOT)
    s = summary(os.path.join(ROOT, "out", "as_built_shaft", "summary.json"))
    print(f"projects/as_built_shaft.json: {t:.1f} s, critical depth {s['critical_depth']:g} m")
    for e in s["sections"]:
        print(f"  {e['depth']:6.2f} m  gap {e['largest_gap']:.3f} m  closure {e['closure_time_days']:.2f} d  "
              f"thinnest {e['thinnest_wall']:.2f} m at {e['thinnest_angle_deg']:.1f} deg  margin {e['design_margin']:.3f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=["ranks", "ring", "shipped"])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--spacing", type=float, default=0.04)
    ap.add_argument("--depths", type=float, nargs="+", default=[30, 60])
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-as-built-")
    try:
        {"ranks": ranks, "ring": ring, "shipped": shipped}[args.what](args, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
