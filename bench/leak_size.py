#!/usr/bin/env python3
"""The CFD-DEM paper's model-size check: the leak case (projects/leak_cavity.json,
grains of 4 mm over a 5 cm cavity that keeps what falls in) with inflow faces
of 15, 20, 30 and 40 cm square, the flow path still 20 cm long. The cavity
keeps its place under the surface (its crown 5 cm down, midway across the
face and along the flow) and point A its 4 cm depth over it; the grains are
as many as fill the box at the 20 cm case's packing; the inflow velocity is
the same. Every run on 2 MPI ranks, its packing cached in ~/.cache/frostwall.
Prints, per face, the wall time, the loss, the crater and the settlement at
the end, and the loss rate over time.

The grains grow as the face: 62 000 at 15 cm, 116 000 at 20, 271 000 at 30
and 488 000 at 40, and the settling and the flow cost grow with them (at
20 cm about 17 minutes of settling and 36 of flow for 1 s on 2 ranks of this
machine). At 15 cm the cavity would touch the floor: it stands a grain above
it, its crown 4.6 cm down instead of 5.

  python3 bench/leak_size.py                          # 15-40 cm, 1 s each
  python3 bench/leak_size.py --faces 0.15 0.2 --end 0.3
  python3 bench/leak_size.py --reuse DIR --faces 0.15 0.2
"""
import argparse, json, math, os

from leak_sweep import run_all, run_project

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def project(face, velocity, end):
    with open(os.path.join(ROOT, "projects", "leak_cavity.json")) as f:
        p = json.load(f)
    x0, length, z0 = p["box"]["high"]
    radius, depth = p["cavity"]["radius"], z0 - p["cavity"]["centre"][2]
    solid = lambda l: l * length * l - 4 / 3 * math.pi * radius ** 3
    g = p["grains"]
    g["count"] = round(g["count"] * solid(face) / solid(x0))
    g["fill"] = {"low": [0, 0, 0], "high": [face, length, face * g["fill"]["high"][2] / z0]}
    p["box"] = {"low": [0, 0, 0], "high": [face, length, face]}
    # The crown as deep as at 20 cm, but the cavity a grain clear of the floor.
    p["cavity"]["centre"] = [face / 2, length / 2, max(face - depth, radius + g["diameter"])]
    p["point_a"] = [face / 2, length / 2, face - 0.04]
    p["flow"]["darcy_velocity"] = velocity
    p["time"] = {"end": end, "unit": "s", "snapshots": [end / 2, end]}
    return p


def run(face, velocity, end, ranks, work):
    directory = os.path.join(work, f"L{face:g}")
    p = project(face, velocity, end)
    p["output"] = {"directory": directory, "vtk": True, "report": True}
    return run_project(p, directory, ranks, f"L = {face:g} m ({p['grains']['count']} grains)")


def table(directories):
    print("\n| face (m) | grains | flow wall s | lost to the cavity | lost / void capacity | zone porosity (end) | "
          "crater depth, width, slope | settlement max | peak KE J |")
    print("|---|---|---|---|---|---|---|---|---|")
    rates = {}
    for face, directory in directories:
        with open(os.path.join(directory, "summary.json")) as f:
            s = json.load(f)
        soil, end = s["soil"], s["soil"]["series"][-1]
        cr = soil.get("crater", {})
        fmt = lambda v, f: (f.format(v) if isinstance(v, (int, float)) else "-")
        print(f"| {face:g} | {s['grains']} | {s['run_wall_time_s']:.0f} | {soil['lost_to_cavity']:.0f} | "
              f"{soil['lost_to_cavity'] / soil['cavity']['capacity_grains']:.2f} | {end['zone_porosity']:.3f} | "
              f"{fmt(cr.get('depth_m'), '{:.3f}')} m, {fmt(cr.get('width_m'), '{:.3f}')} m, "
              f"{fmt(cr.get('slope_deg'), '{:.1f}')} deg | {1e3 * end['settlement_max_m']:.1f} mm | "
              f"{s['stability']['peak_kinetic_energy_J']:.3g} |")
        rates[face] = [(r["time"], r.get("loss_rate", 0.0)) for r in soil["series"]]
    print("\nThe loss rate (grains lost in a period over the count at the previous period) at every 0.1 s:\n")
    faces = list(rates)
    print("| t (s) | " + " | ".join(f"{f:g} m" for f in faces) + " |")
    print("|---|" + "---|" * len(faces))
    times = [t for t, _ in rates[faces[0]]] if faces else []
    for k, t in enumerate(times):
        if k % 20 == 0 or k == len(times) - 1:
            print(f"| {t:.2f} | " + " | ".join(
                f"{rates[f][k][1]:.2e}" if k < len(rates[f]) else "-" for f in faces) + " |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--faces", type=float, nargs="+", default=[0.15, 0.2, 0.3, 0.4])
    parser.add_argument("--velocity", type=float, default=0.1)
    parser.add_argument("--end", type=float, default=1.0)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--reuse", help="a directory holding L<face>/ runs: tables only")
    args = parser.parse_args()
    dirs = run_all(args.faces, lambda f: f"L{f:g}", args.reuse, "frostwall-leak-size-",
                   lambda f, work: run(f, args.velocity, args.end, args.ranks, work))
    table(dirs)


if __name__ == "__main__":
    main()
