#!/usr/bin/env python3
"""Stiffness scaling of the leak case's grains: softer grains allow a longer
DEM step (the Rayleigh time grows as 1 / sqrt(E)), so dividing Young's
modulus by s^2 cuts the steps of a run by s. This script measures what the
lever changes, against the stiff run and against the seed-to-seed spread:

  heap   the scaled repose heap (1 200 grains of 6 mm, E = 1e7 Pa, sides lifted
         at 5 mm/s): its angle of repose;
  leak   the scaled leak at 0.3 m/s (2 200 grains of 8 mm over a kept cavity,
         strong packing): the grains lost to the cavity, the crater's depth and
         flank slope, the peak kinetic energy;
  full   the full case's grains (projects/verify_repose.json, 5 000 grains of
         4 mm, E = 5e7 Pa): its angle of repose (the DEM step set at 0.3 of the
         Rayleigh time, as projects/leak_cavity.json sets it). Long: about
         15 minutes a run here; only with --full.

Each case runs at every softening (E divided by 1, 2.25 and 5.3: steps 1,
1.5 and 2.3 times longer) and every seed; the steps are the chosen ones (a
fifth of the Rayleigh time) for the scaled cases. The runs go two at a time
(one rank each); the tables give the mean over the seeds, the spread
(largest minus smallest) and each softening's change from the stiff mean.

  python3 bench/leak_stiffness.py                    # heap and leak, seeds 1-3
  python3 bench/leak_stiffness.py --cases heap --seeds 1 2
  python3 bench/leak_stiffness.py --cases full --seeds 1
"""
import argparse, concurrent.futures, json, math, os, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
SOFTENINGS = [1.0, 2.25, 5.3]
OUTPUT = {"directory": "out", "report": False, "vtk": False}


def heap(seed):
    return {"name": "repose heap, scaled", "physics": "cfd-dem",
            "box": {"low": [0, 0, 0], "high": [0.24, 0.24, 0.15]},
            "grains": {"diameter": 0.006, "density": 2650, "count": 1200, "youngs_modulus": 1e7, "poisson_ratio": 0.3,
                       "restitution": 0.5, "friction": 0.5, "rolling_friction": 0.1, "seed": seed,
                       "settle_time": 0.3, "fill": {"low": [0.08, 0.08, 0], "high": [0.16, 0.16, 0.15]}},
            "heap": {}, "fluid": {"density": 1000, "viscosity": 0.001, "cell_size": 0.02},
            "time": {"end": 6.5, "unit": "s", "snapshots": [6.5]}, "output": OUTPUT}


def leak(seed):
    return {"name": "leak at 0.3 m/s, scaled", "physics": "cfd-dem",
            "box": {"low": [0, 0, 0], "high": [0.1, 0.1, 0.1]},
            "grains": {"diameter": 0.008, "density": 2650, "count": 2200, "youngs_modulus": 1e7, "poisson_ratio": 0.3,
                       "restitution": 0.5, "friction": 0.8, "rolling_friction": 0.5, "settle_friction": 0.1,
                       "seed": seed, "settle_time": 0.4, "fill": {"low": [0, 0, 0], "high": [0.1, 0.1, 0.18]}},
            "cavity": {"centre": [0.05, 0.05, 0.06], "radius": 0.025}, "point_a": [0.05, 0.05, 0.09],
            "fluid": {"density": 1000, "viscosity": 0.001, "cell_size": 0.01},
            "flow": {"inflow": "y_min", "darcy_velocity": 0.3, "outflow": "y_max"},
            "time": {"end": 1.0, "unit": "s", "snapshots": [0.5, 1.0]}, "output": OUTPUT}


def full(seed):
    with open(os.path.join(ROOT, "projects", "verify_repose.json")) as f:
        p = json.load(f)
    p["grains"]["seed"] = seed
    p["output"] = OUTPUT
    return p


CASES = {"heap": heap, "leak": leak, "full": full}


def soften(project, s2):
    p = json.loads(json.dumps(project))
    p["grains"]["youngs_modulus"] /= s2
    if "dem_timestep" in p.get("coupling", {}):
        p["coupling"]["dem_timestep"] *= math.sqrt(s2)
    return p


def run(case, seed, s2, work):
    directory = os.path.join(work, f"{case}-s{s2:g}-seed{seed}")
    os.makedirs(directory)
    with open(os.path.join(directory, "p.json"), "w") as f:
        json.dump(soften(CASES[case](seed), s2), f)
    # Each run has its own packing cache: the settling is part of what softening changes.
    env = dict(os.environ, CI="1", FROSTWALL_CACHE=os.path.join(directory, "cache"), OMP_NUM_THREADS="1")
    start = time.perf_counter()
    done = subprocess.run([EXE, "run", "p.json"], cwd=directory, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True, env=env)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        print(f"{case} E/{s2:g} seed {seed}: exit {done.returncode}: {done.stderr.strip()}", flush=True)
        return case, seed, s2, wall, None
    with open(os.path.join(directory, "out", "summary.json")) as f:
        summary = json.load(f)
    print(f"{case} E/{s2:g} seed {seed}: {wall:.0f} s", flush=True)
    return case, seed, s2, wall, summary


def measures(case, s):
    if case in ("heap", "full"):
        return {"repose deg": s["angle_of_repose_deg"]}
    soil, crater = s["soil"], s["soil"].get("crater", {})
    return {"lost": soil["series"][-1]["lost_to_cavity"], "crater mm": 1e3 * (crater.get("depth_m") or 0.0),
            "flank deg": crater.get("slope_deg") or float("nan"),
            "peak KE J": s["stability"]["peak_kinetic_energy_J"]}


def table(case, results, softenings):
    rows = [(seed, s2, wall, summary) for c, seed, s2, wall, summary in results if c == case and summary]
    if not rows:
        return
    names = list(measures(case, rows[0][3]).keys())
    print(f"\n{case}:\n")
    print("| E divided by | DEM step s | steps | wall s (mean) | " + " | ".join(
        f"{n}: mean, spread, change" for n in names) + " |")
    print("|---|---|---|---|" + "---|" * len(names))
    stiff = {}
    for s2 in softenings:
        mine = [r for r in rows if r[1] == s2]
        if not mine:
            continue
        cells = []
        for n in names:
            values = [measures(case, r[3])[n] for r in mine]
            mean = sum(values) / len(values)
            stiff.setdefault(n, mean)
            cells.append(f"{mean:.3g}, {max(values) - min(values):.3g}, {mean - stiff[n]:+.3g}")
        s = mine[0][3]
        print(f"| {s2:g} | {s['dem_timestep_s']:.3g} | {s['dem_steps']} | "
              f"{sum(r[2] for r in mine) / len(mine):.0f} | " + " | ".join(cells) + " |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cases", nargs="+", default=["heap", "leak"], choices=list(CASES))
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--softenings", type=float, nargs="+", default=SOFTENINGS)
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-stiffness-")
    print(f"runs in {work}", flush=True)
    jobs = [(c, seed, s2) for c in args.cases for s2 in args.softenings for seed in args.seeds]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda j: run(*j, work), jobs))
    for case in args.cases:
        table(case, results, args.softenings)


if __name__ == "__main__":
    main()
