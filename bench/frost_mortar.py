#!/usr/bin/env python3
"""The PD paper's frost-damage case, projects/mortar_frost.json (300 um
mortar plate, eight water-filled pores, -30 C on two faces), through
`frostwall run` on 2 threads: wall time, heat steps, relaxations, ADR
iterations, when each pore froze and how much broke, at each spacing asked
(default the shipped 3 um, from which the cracks converge; the paper's 1 um
takes hours; coarser ones show the trend).

  python3 bench/frost_mortar.py              # the whole run at the shipped 3 um
  python3 bench/frost_mortar.py 1e-6         # at the paper's 1 um (hours)
  python3 bench/frost_mortar.py 6e-6 4e-6    # coarser spacings, in order
  python3 bench/frost_mortar.py --end 0.03   # a shorter run
  python3 bench/frost_mortar.py 2e-6 --fracture-energy 30 --model ice_eigenstrain
  python3 bench/frost_mortar.py --main-job   # and the still-water main job, as a ratio

Per snapshot it prints the crack measures (the damage-0.4 isolines'
length and per area, the broken-bond energy); with several spacings the
last two are compared.
"""
import argparse, json, os, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")


def run_timed(project, path, threads):
    """Writes project to path, runs it; the wall time in seconds."""
    with open(path, "w") as f:
        json.dump(project, f)
    start = time.perf_counter()
    subprocess.run([EXE, "--threads", str(threads), "run", path], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, env=dict(os.environ, CI="1"))
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("spacings", nargs="*", type=float, default=[3e-6])
    ap.add_argument("--end", type=float, default=None, help="stop the run here (s)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--fracture-energy", type=float, default=None, help="G0 in J/m2 instead of the project's")
    ap.add_argument("--model", default=None, help="freezing_expansion model instead of the project's")
    ap.add_argument("--saturation", type=float, default=None, help="every pore's degree of saturation")
    ap.add_argument("--main-job", action="store_true", help="also time the main job (the single ring in sand)")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-frost-bench-")
    with open(os.path.join(ROOT, "projects", "mortar_frost.json")) as f:
        base = json.load(f)
    main_wall = None
    if args.main_job:
        with open(os.path.join(ROOT, "projects", "single_ring_sand.json")) as f:
            ring = json.load(f)
        ring["output"]["directory"] = os.path.join(work, "main_job")
        main_wall = run_timed(ring, os.path.join(work, "main_job.json"), args.threads)
        print(f"main job (single ring in sand), {args.threads} threads: {main_wall:.1f} s wall", flush=True)
    measures = []
    for dx in args.spacings:
        project = json.loads(json.dumps(base))
        project["numerics"]["spacing"] = dx
        if args.fracture_energy:
            project["mechanics"]["material"]["fracture_energy"] = args.fracture_energy
        if args.model:
            project["mechanics"]["freezing_expansion"]["model"] = args.model
        if args.saturation:
            project["geometry"]["saturation"] = args.saturation
        if args.end:
            project["time"] = {"end": args.end, "unit": "s",
                               "snapshots": [t for t in base["time"]["snapshots"] if t < args.end] + [args.end]}
        out = os.path.join(work, f"dx{dx:g}")
        project["output"] = {"directory": out, "vtk": False, "report": False}
        wall = run_timed(project, out + ".json", args.threads)
        if main_wall:
            print(f"spacing {dx:g} m: {wall / main_wall:.1f} x the main job", flush=True)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        run, mech = s["run"], s["run"]["mechanics"]
        kind = "CG" if mech.get("equilibrium") == "direct" else "ADR"
        print(f"spacing {dx:g} m, {args.threads} threads: {wall:.1f} s wall; {run['particles']} particles, "
              f"{mech['bonds']} bonds, {run['steps']} heat steps, {mech['relaxations']} relaxations, "
              f"{mech['relaxation_iterations']} {kind} iterations (longest {mech['longest_relaxation']}), "
              f"{mech.get('factorizations', 0)} factorizations, {mech.get('direct_solves', 0)} equilibria, "
              f"{mech['broken_bonds']} bonds broken", flush=True)
        for p in s["pores"]:
            print(f"  pore {p['id']}: freezes {p['freezing_start']} .. {p['freezing_end']} s, "
                  f"largest rim damage {p['max_rim_damage']:.2f}")
        print(f"  every pore frozen at {s['all_pores_frozen']} s; broken bonds within a pore radius of a rim: "
              f"{s['broken_bonds_near_rims']}; first damage {mech['first_damage']}")
        for d in s["damage"]:
            print(f"  t = {d['time']:g} s: {100 * d['broken_bond_share']:.2f} % of bonds broken, "
                  f"largest damage {d['largest_damage']:.2f}, damaged area {d['damaged_area'] * 1e12:.0f} um2, "
                  f"crack lines {d['crack_length'] * 1e6:.0f} um ({d['crack_length_per_area'] * 1e-3:.2f} /mm), "
                  f"broken-bond energy {d['broken_bond_energy'] * 1e3:.3f} mJ/m")
        measures.append((dx, s["damage"][-1]))
    if len(measures) >= 2:
        (a, da), (b, db) = measures[-2], measures[-1]
        for key in ("crack_length", "broken_bond_energy"):
            print(f"{key}: {db[key]:.4g} at {b:g} m against {da[key]:.4g} at {a:g} m ({100 * (db[key] / da[key] - 1):+.1f} %)")


if __name__ == "__main__":
    main()
