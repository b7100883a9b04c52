#!/usr/bin/env python3
"""CFD-DEM speed at the paper's scale: a 0.2 m cube of 4 mm grains round a
5 cm cavity, 1 cm fluid cells (20^3), water entering the y = 0 face at
0.1 m/s, run through `frostwall run` on 1 and on 2 MPI ranks in one script
run. Prints DEM particle-steps per second per core and the coupling's share
of the wall time (fluid grid, deposits, forces; the target is < 10 %).

  python3 bench/cfd_dem_rate.py              # 80 000 grains settled, then 0.04 s of flow
  python3 bench/cfd_dem_rate.py --grains 20000 --end 0.01 --settle 0.05
The settling (the first run's) is not in the rates: each run's own
summary.json times only the flow.
"""
import argparse, json, os, shutil, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")


def project(grains, end, directory, settle):
    return {
        "name": "CFD-DEM rate at the paper's scale", "physics": "cfd-dem",
        "box": {"low": [0, 0, 0], "high": [0.2, 0.2, 0.2]},
        "grains": {"diameter": 0.004, "density": 2650, "count": grains, "youngs_modulus": 5e7,
                   "restitution": 0.5, "friction": 0.5, "seed": 1, "settle_time": settle},
        "cavity": {"centre": [0.1, 0.1, 0.1], "radius": 0.05},
        "fluid": {"density": 1000, "viscosity": 0.001, "cell_size": 0.01},
        "flow": {"inflow": "y_min", "darcy_velocity": 0.1, "outflow": "y_max"},
        "time": {"end": end, "unit": "s"},
        "output": {"directory": directory, "vtk": False, "report": False},
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--grains", type=int, default=80000)
    parser.add_argument("--end", type=float, default=0.04)
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2],
                        help="MPI rank counts to run (more than the cores: oversubscribed)")
    parser.add_argument("--settle", type=float, default=0.15,
                        help="s of settling first (cached in ~/.cache/frostwall: the first run pays it once)")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-cfd-dem-bench-")
    rates = {}
    for ranks in args.ranks:
        directory = os.path.join(work, f"r{ranks}")
        path = os.path.join(work, f"p{ranks}.json")
        with open(path, "w") as f:
            json.dump(project(args.grains, args.end, directory, args.settle), f)
        launcher = [] if ranks == 1 else ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)]
        start = time.perf_counter()
        subprocess.run(launcher + [EXE, "run", path], check=True, stderr=subprocess.DEVNULL, env=dict(os.environ, CI="1"))
        wall = time.perf_counter() - start
        with open(os.path.join(directory, "summary.json")) as f:
            s = json.load(f)
        steps = s["dem_steps"] * s["grains"]
        rates[ranks] = steps / s["run_wall_time_s"] / ranks
        print(f"{ranks} rank{'s' if ranks > 1 else ''}: {s['grains']} grains, {s['dem_steps']} DEM steps of "
              f"{s['dem_timestep_s']:.3g} s, fluid every {s['coupling_interval']}; run {s['run_wall_time_s']:.1f} s "
              f"(process {wall:.1f} s); {rates[ranks]:.3g} particle-steps/s per core; coupling "
              f"{100 * s['coupling_share']:.1f} % of the run", flush=True)
    first = args.ranks[0]
    for ranks in args.ranks[1:]:
        print(f"{ranks} ranks against {first}: {ranks * rates[ranks] / (first * rates[first]):.2f}x the rate "
              f"({rates[ranks] / rates[first]:.2f} per core)")
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
