#!/usr/bin/env python3
"""The CFD-DEM paper's four inflow velocities at full size: projects/leak_cavity.json
(116 000 grains of 4 mm over a 5 cm cavity that keeps what falls in) at
0.001, 0.1, 0.2 and 0.3 m/s, 1 s of flow each, every run on 2 MPI ranks
from the one settled packing (cached in ~/.cache/frostwall: the first run
settles it). Prints, per velocity, the wall time of the flow, the losses,
the crater and the slip surface, the paper's series (loss rate, change in
contacts, porosity over the cavity, pressure drop to point A, the forces on
point A's grains), and which of the paper's trends the runs reproduce.

  python3 bench/leak_sweep.py                       # the four velocities, 1 s each
  python3 bench/leak_sweep.py --velocities 0.1 --end 0.2
  python3 bench/leak_sweep.py --drain               # grains that fall in deleted (a leak into a pipe)
  python3 bench/leak_sweep.py --soften 5.3          # Young's modulus / 5.3, the DEM step x 2.3 (bench/leak_stiffness.py)
  python3 bench/leak_sweep.py --reuse DIR           # only the tables, from the runs in DIR
"""
import argparse, json, math, os, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
BUOYANCY = 1000 * 9.81 * math.pi / 6 * 0.004 ** 3  # rho_w g V of a 4 mm grain, N


def norm(v):
    return math.sqrt(sum(x * x for x in v))


def run(velocity, end, ranks, drain, soften, work):
    with open(os.path.join(ROOT, "projects", "leak_cavity.json")) as f:
        p = json.load(f)
    p["grains"]["youngs_modulus"] /= soften
    p["coupling"]["dem_timestep"] *= math.sqrt(soften)
    p["flow"]["darcy_velocity"] = velocity
    p["time"] = {"end": end, "unit": "s", "snapshots": [end / 4 * k for k in range(1, 5)]}
    directory = os.path.join(work, f"U{velocity:g}")
    p["output"] = {"directory": directory, "vtk": True, "report": True}
    if drain:
        p["cavity"]["drain"] = True
    return run_project(p, directory, ranks, f"U = {velocity:g} m/s")


def run_project(p, directory, ranks, label):
    """Runs project p (its output in directory) on `ranks` MPI ranks; directory, or None if it failed."""
    path = directory + ".json"
    with open(path, "w") as f:
        json.dump(p, f)
    start = time.perf_counter()
    done = subprocess.run(["mpirun", "--allow-run-as-root", "-np", str(ranks), EXE, "run", path],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=dict(os.environ, CI="1"))
    print(f"{label}: {time.perf_counter() - start:.0f} s in all, exit status {done.returncode}", flush=True)
    if done.returncode != 0:
        print("  " + "".join(line for line in done.stderr.splitlines(True) if "frostwall" in line).strip(), flush=True)
        return None
    return directory


def run_all(keys, name, reuse, prefix, run_one):
    """(key, run directory) of every run that succeeded: directory/<name(key)>, from `reuse` or a new
    temporary directory in which run_one(key, work) runs each."""
    if reuse:
        return [(k, os.path.join(reuse, name(k))) for k in keys]
    work = tempfile.mkdtemp(prefix=prefix)
    print(f"runs in {work}", flush=True)
    return [(k, d) for k, d in ((k, run_one(k, work)) for k in keys) if d]


def interval(stability):
    steps = stability.get("interval_steps")
    if not steps:
        return "-"
    if steps["given"]:
        return f"{steps['longest']} (given)"
    return f"{steps['shortest']}-{steps['longest']}"


def table(directories):
    rows = {}
    for velocity, directory in directories:
        with open(os.path.join(directory, "summary.json")) as f:
            rows[velocity] = json.load(f)
    print("\n| U (m/s) | flow wall s | DEM steps | lost to the cavity | in it at the end | the void holds | "
          "zone porosity (end) | crater depth, width, slope | trough m3 | slip surface | settlement max | "
          "interval steps | peak KE J (at s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for u, s in rows.items():
        soil = s["soil"]
        end = soil["series"][-1]
        cr = soil.get("crater", {})
        fmt = lambda v, f: (f.format(v) if isinstance(v, (int, float)) else "-")
        print(f"| {u:g} | {s['run_wall_time_s']:.0f} | {s['dem_steps']} | {soil['lost_to_cavity']:.0f} | "
              f"{soil.get('grains_in_cavity_at_end', float('nan')):.0f} | "
              f"{soil.get('cavity', {}).get('capacity_grains', float('nan')):.0f} | {end['zone_porosity']:.3f} | "
              f"{fmt(cr.get('depth_m'), '{:.3f}')} m, {fmt(cr.get('width_m'), '{:.3f}')} m, {fmt(cr.get('slope_deg'), '{:.1f}')} deg | "
              f"{fmt(cr.get('volume_m3'), '{:.2e}')} | {fmt(soil.get('slip_surface_angle_deg'), '{:.0f}')} deg | "
              f"{1e3 * end['settlement_max_m']:.1f} mm | {interval(s['stability'])} | "
              f"{s['stability']['peak_kinetic_energy_J']:.3g} ({s['stability']['peak_kinetic_energy_at_s']:.2f}) |")
    print("\nThe paper's series at the output times (every 0.1 s):")
    print("\n| U (m/s) | t (s) | loss rate | contact change | zone porosity | dP inflow to A (Pa) | drag at A (N) | "
          "pressure-gradient force at A (N) | buoyancy at A (N) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for u, s in rows.items():
        series = s["soil"]["series"]
        for k, r in enumerate(series):
            if k % 20 != 0 and k != len(series) - 1:
                continue
            print(f"| {u:g} | {r['time']:.2f} | {r.get('loss_rate', 0):.2e} | {r.get('contact_change', 0):.0f} | "
                  f"{r['zone_porosity']:.3f} | {r['pressure_drop_to_a_Pa'] or 0:.0f} | {norm(r['mean_drag_at_a_N']):.2e} | "
                  f"{norm(r['mean_pressure_gradient_force_at_a_N']):.2e} | {norm(r['mean_buoyancy_at_a_N']):.3e} |")
    print("\nThe paper's trends:")
    us = sorted(rows)
    lost = [rows[u]["soil"]["lost_to_cavity"] for u in us]
    rises = all(b > 1.01 * a for a, b in zip(lost, lost[1:]))
    print(f"- loss rises with velocity by more than 1 % at each step: {'yes' if rises else 'no'} "
          f"({', '.join(f'{x:.0f}' for x in lost)})")
    for u in us:
        series = rows[u]["soil"]["series"]
        changes = [r.get("contact_change", 0) for r in series[1:]]
        first = next((c for c in changes if c != 0), 0)
        later = sum(changes[len(changes) // 4:])  # after the first quarter of the run
        later_pos = first < 0 and later > 0
        zone = [r["zone_porosity"] for r in series]
        with_grains = [r for r in series[1:] if r["grains_at_a"] > 0]  # A's cell empties once the zone falls in
        pg = [norm(r["mean_pressure_gradient_force_at_a_N"]) for r in with_grains]
        drag = [norm(r["mean_drag_at_a_N"]) for r in with_grains]
        buoy = [norm(r["mean_buoyancy_at_a_N"]) for r in series[1:] if r["grains_at_a"] > 0]
        print(f"- U = {u:g}: contact change negative first (first change {first:.0f}), positive after the first quarter "
              f"(sum {later:.0f}): {'yes' if later_pos else 'no'}; zone porosity "
              f"{zone[0]:.3f} -> {zone[len(zone) // 2]:.3f} (half time) -> {zone[-1]:.3f}; pressure-gradient force over drag at A "
              f"(while grains are there, {len(with_grains)} outputs) {sum(pg) / max(1e-30, sum(drag)):.2f}, the pressure-gradient "
              f"force at the start {norm(series[0]['mean_pressure_gradient_force_at_a_N']):.2e} N; buoyancy per grain at A "
              f"{(sum(buoy) / len(buoy)) if buoy else float('nan'):.4g} N (rho_w g V = {BUOYANCY:.4g} N)")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--velocities", type=float, nargs="+", default=[0.001, 0.1, 0.2, 0.3])
    parser.add_argument("--end", type=float, default=1.0)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--drain", action="store_true")
    parser.add_argument("--soften", type=float, default=1.0, help="divide Young's modulus by this, the step grows as its root")
    parser.add_argument("--reuse", help="a directory holding U<velocity>/ runs: tables only")
    args = parser.parse_args()
    dirs = run_all(args.velocities, lambda u: f"U{u:g}", args.reuse, "frostwall-leak-sweep-",
                   lambda u, work: run(u, args.end, args.ranks, args.drain, args.soften, work))
    table(dirs)


if __name__ == "__main__":
    main()
