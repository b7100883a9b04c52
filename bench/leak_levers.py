#!/usr/bin/env python3
"""What each speed lever buys on the CFD-DEM leak case, as ratios
in one script run, and whether the answer moves with it.

Part A, the paper's case (projects/leak_cavity.json: 116 000 grains, 0.2 m
cube, 0.1 m/s) from its cached settled packing (the first run ever settles
it, about 10 min on 2 ranks), a short stretch of flow per variant:
  - LAMMPS' neighbour lists: skin, steps between checks, bin size;
  - the coupling interval (DEM steps per fluid update).
Part B, the DEM step (0.2 of the Rayleigh time by default) on the scaled
leak case of the tests (0.1 m cube, 6 mm grains, at 0.3 m/s, where the
loss is hundreds of grains; near the threshold it is a few tens and swings
with the packing), over three packings (seeds): a coarser step
settles its own packing (the step is part of the packing's cache key), so
it is measured where settling is cheap; the grains lost and the settled
porosity show whether the answer holds.

  python3 bench/leak_levers.py                # both parts, 2 ranks, 0.04 s of flow in part A
  python3 bench/leak_levers.py --part B --ranks 1
"""
import argparse, json, math, os, shutil, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")


def run(project, work, name, ranks):
    """Runs a project; returns its summary, wall time and peak memory (MB, the largest process)."""
    directory = os.path.join(work, name)
    project = dict(project, output={"directory": directory, "vtk": False, "report": False})
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(project, f)
    launcher = [] if ranks == 1 else ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)]
    # GNU time's %M: the largest resident set of any one process (a rank).
    memory = os.path.join(work, name + ".rss")
    timer = ["/usr/bin/time", "-f", "%M", "-o", memory] if os.path.exists("/usr/bin/time") else []
    start = time.perf_counter()
    done = subprocess.run(timer + launcher + [EXE, "run", path], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          env=dict(os.environ, CI="1"))
    wall = time.perf_counter() - start
    if done.returncode != 0:  # say why (a step too coarse loses grains) and go on
        lines = [l.strip() for l in done.stderr.splitlines() if "ERROR" in l or l.startswith("frostwall:")]
        raise RuntimeError(lines[0] if lines else f"exit status {done.returncode}")
    peak = float("nan")
    if timer:
        with open(memory) as f:
            peak = float(f.read().split()[-1])
    with open(os.path.join(directory, "summary.json")) as f:
        s = json.load(f)
    return s, wall, peak / 1024.0


def rate(s, ranks):
    return s["dem_steps"] * s["grains"] / s["run_wall_time_s"] / ranks


def end_state(s):
    soil = s["soil"]
    last = soil["series"][-1]
    return soil["lost_to_cavity"], last["zone_porosity"], last["settlement_max_m"]


def part_a(work, ranks, end, only):
    with open(os.path.join(ROOT, "projects", "leak_cavity.json")) as f:
        base = json.load(f)
    base["time"] = {"end": end, "unit": "s", "snapshots": [end]}
    d = base["grains"]["diameter"]
    variants = [("baseline: skin d/4, check every step, bins of half the cutoff, fluid every 250 steps", {}),
                ("skin d/8", {"neighbour": {"skin": d / 8}}),
                ("skin d/2", {"neighbour": {"skin": d / 2}}),
                ("check every 2 steps", {"neighbour": {"every": 2}}),
                ("check every 5 steps", {"neighbour": {"every": 5}}),
                ("bins of d", {"neighbour": {"bin_size": d}}),
                ("bins of 1.25 d (the cutoff)", {"neighbour": {"bin_size": 1.25 * d}}),
                ("fluid every 50 steps", {"coupling": {"interval": 50}}),
                ("fluid every 25 steps", {"coupling": {"interval": 25}})]
    print(f"Part A: projects/leak_cavity.json, {ranks} rank(s), {end} s of flow from the cached packing", flush=True)
    first = None
    for k, (label, change) in enumerate(variants):
        if k > 0 and only and not any(word in label for word in only):
            continue
        p = dict(base, **change)
        s, wall, peak = run(p, work, f"a{k}", ranks)
        r = rate(s, ranks)
        lost, zone, settle = end_state(s)
        if first is None:
            first = (r, lost, zone, settle)
            if not s["packing"]["read_from_cache"]:
                print("  (the packing was settled in this run and is now cached)")
        print(f"  {label}: {s['dem_steps']} steps, fluid every {s['coupling_interval']}, run {s['run_wall_time_s']:.1f} s "
              f"(process {wall:.0f} s, peak {peak:.0f} MB); {r:.3g} particle-steps/s per core = {r / first[0]:.2f}x; "
              f"coupling {100 * s['coupling_share']:.1f} %; lost {lost:.0f} (baseline {first[1]:.0f}), "
              f"zone porosity {zone:.4f} ({first[2]:.4f}), settlement {1e3 * settle:.2f} mm ({1e3 * first[3]:.2f})", flush=True)


def scaled_case(dt, seed):
    p = {"name": "leak over a cavity, scaled", "physics": "cfd-dem",
         "box": {"low": [0, 0, 0], "high": [0.1, 0.1, 0.1]},
         "grains": {"diameter": 0.006, "density": 2650, "count": 5000, "youngs_modulus": 1e7, "poisson_ratio": 0.3,
                    "restitution": 0.5, "friction": 0.8, "rolling_friction": 0.5, "settle_friction": 0.1,
                    "seed": seed, "settle_time": 0.4, "fill": {"low": [0, 0, 0], "high": [0.1, 0.1, 0.18]}},
         "cavity": {"centre": [0.05, 0.05, 0.06], "radius": 0.025},
         "fluid": {"density": 1000, "viscosity": 0.001, "cell_size": 0.01},
         "flow": {"inflow": "y_min", "darcy_velocity": 0.3, "outflow": "y_max"},
         "time": {"end": 0.3, "unit": "s", "snapshots": [0.3]}}
    if dt:
        p["coupling"] = {"dem_timestep": dt}
    return p


def hertz_contact_time(p, speed):
    """Hertz's duration of a head-on impact of two equal grains at `speed` (m/s)."""
    g = p["grains"]
    m = g["density"] * math.pi / 6 * g["diameter"] ** 3
    e_star = g["youngs_modulus"] / (2 * (1 - g["poisson_ratio"] ** 2))
    return 2.87 * ((m / 2) ** 2 / (g["diameter"] / 4 * e_star ** 2 * speed)) ** 0.2


def part_b(work, ranks, seeds):
    cache = os.path.join(work, "cache")
    os.environ["FROSTWALL_CACHE"] = cache  # every step settles its own packing here
    print(f"Part B: the scaled leak case (5 000 grains of 6 mm, 0.3 m/s, 0.3 s), {ranks} rank(s), packings from "
          f"seeds {seeds}; each step settles its own packings (0.4 s) first", flush=True)
    t_c = hertz_contact_time(scaled_case(None, 1), 1.0)
    dt0, wall0 = None, None
    for factor in (1.0, 1.5, 2.0, 2.5):
        runs = []
        try:
            for seed in seeds:
                s, wall, _ = run(scaled_case(dt0 and factor * dt0, seed), work, f"b{factor}-{seed}", ranks)
                runs.append((s, wall))
        except RuntimeError as failure:
            print(f"  step {factor:.1f}x ({factor * 0.2:.2f} of the Rayleigh time): a run failed: {failure}", flush=True)
            continue
        dt = runs[0][0]["dem_timestep_s"]
        dt0 = dt0 or dt
        wall = sum(w for _, w in runs) / len(runs)
        wall0 = wall0 or wall
        lost = [s["soil"]["lost_to_cavity"] for s, _ in runs]
        porosity = [s["soil"]["regime"]["porosity"] for s, _ in runs]
        zone = [s["soil"]["series"][-1]["zone_porosity"] for s, _ in runs]
        print(f"  step {factor:.1f}x ({dt:.3g} s, {factor * 0.2:.2f} of the Rayleigh time; a 1 m/s impact lasts "
              f"{t_c / dt:.0f} steps): {wall:.1f} s a run = {wall0 / wall:.2f}x faster; settled porosity "
              f"{min(porosity):.4f}-{max(porosity):.4f}; lost {', '.join(f'{x:.0f}' for x in lost)} "
              f"(mean {sum(lost) / len(lost):.0f}); zone porosity {min(zone):.3f}-{max(zone):.3f}", flush=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--part", choices=["A", "B", "AB"], default="AB")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--end", type=float, default=0.04, help="s of flow per variant in part A")
    parser.add_argument("--only", nargs="*", default=[], help="part A: the baseline and the variants whose label holds one of these words")
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3], help="packings per step in part B")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-leak-levers-")
    try:
        if "A" in args.part:
            part_a(work, args.ranks, args.end, args.only)
        if "B" in args.part:
            part_b(work, args.ranks, args.seeds)
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
