#!/usr/bin/env python3
"""Calibration twins: readings of `frostwall run`, recovered by `frostwall calibrate`.

  python3 bench/calibration_twins.py                 # the three twins below, seed 1
  python3 bench/calibration_twins.py --seeds 1 2 3 4 --twins A

Each twin is the single ring in sand to day 30 with three thermometers (N1
in the neck at r 5.0 m and 6.923 deg, O1 outside at 5.9 m, I1 inside at
4.2 m and 3 deg) and a ground of its own: the sand's frozen and unfrozen
conductivities and latent heat times its factors. `frostwall run` runs it;
its monitoring.csv to day 20 (every sample, 0.15 d apart) with 0.1 K of
Gaussian noise of the seed is the readings; `frostwall calibrate` fits the
untouched project's three factors to them. Printed per twin and seed: each
factor against the truth with its 95 % interval, the wall time of the
calibration, and the twin's closure day against the forecast's band.
"""
import argparse, csv, json, os, random, shutil, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
SAND = dict(density=2090, unfrozen=1.86, unfrozen_c=1465.1, frozen=2.56, frozen_c=1088.4, latent=52875.8)
TWINS = {  # conductivity_frozen, conductivity_unfrozen, latent_heat
    "A": (0.88, 1.10, 1.08),
    "B": (1.12, 0.92, 0.94),
    "C": (1.05, 1.20, 0.85),
}
NAMES = ("conductivity_frozen", "conductivity_unfrozen", "latent_heat")


def project(directory):
    p = json.load(open(os.path.join(ROOT, "projects", "single_ring_sand.json")))
    p["time"] = {"end": 30, "unit": "d", "snapshots": [10, 20, 30]}
    p["monitoring"] = [{"name": "N1", "r": 5.0, "theta_deg": 6.923}, {"name": "O1", "r": 5.9, "theta_deg": 0.0},
                       {"name": "I1", "r": 4.2, "theta_deg": 3.0}]
    p["output"] = {"directory": directory, "vtk": False, "full_ring": False, "report": False}
    return p


def run_twin(tmp, factors):
    p = project("twin")
    kf, ku, L = factors
    p["soil"] = {"name": "twin", "density": SAND["density"],
                 "unfrozen": {"conductivity": SAND["unfrozen"] * ku, "heat_capacity": SAND["unfrozen_c"]},
                 "frozen": {"conductivity": SAND["frozen"] * kf, "heat_capacity": SAND["frozen_c"]},
                 "latent_heat": SAND["latent"] * L, "freezing_point": 0.0}
    json.dump(p, open(os.path.join(tmp, "twin.json"), "w"))
    subprocess.run([EXE, "run", "twin.json"], cwd=tmp, check=True, capture_output=True)
    rows = list(csv.DictReader(open(os.path.join(tmp, "twin", "monitoring.csv"))))
    closure = json.load(open(os.path.join(tmp, "twin", "summary.json")))["closure_time_days"]
    return rows, closure


def calibrate(tmp, rows, seed):
    rng = random.Random(seed)
    lines = ["sensor,time,temperature"]
    for s in ("N1", "O1", "I1"):
        for r in rows:
            if float(r["day"]) <= 20 + 1e-9:
                lines.append(f"{s},{r['day']},{float(r[s + '_C']) + rng.gauss(0.0, 0.1):.4f}")
    open(os.path.join(tmp, "readings.csv"), "w").write("\n".join(lines) + "\n")
    p = project("fit")
    p["calibrate"] = {"readings": "readings.csv", "parameters": {n: [0.5, 2.0] for n in NAMES}}
    json.dump(p, open(os.path.join(tmp, "fit.json"), "w"))
    shutil.rmtree(os.path.join(tmp, "fit"), ignore_errors=True)
    start = time.perf_counter()
    subprocess.run([EXE, "calibrate", "fit.json"], cwd=tmp, check=True, capture_output=True)
    seconds = time.perf_counter() - start
    return json.load(open(os.path.join(tmp, "fit", "summary.json")))["calibration"], seconds


def main():
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("--twins", nargs="*", default=list(TWINS))
    a.add_argument("--seeds", nargs="*", type=int, default=[1])
    args = a.parse_args()
    tmp = tempfile.mkdtemp(prefix="frostwall-bench-twins-")
    try:
        for name in args.twins:
            rows, closure = run_twin(tmp, TWINS[name])
            for seed in args.seeds:
                c, seconds = calibrate(tmp, rows, seed)
                ok = True
                print(f"twin {name} {TWINS[name]}, seed {seed}: calibrate {seconds:.1f} s "
                      f"({c['iterations']} iterations, {c['forward_runs']} runs), rms misfit "
                      f"{c['rms_misfit_after']:.4f} K")
                for j, n in enumerate(NAMES):
                    q, t = c["parameters"][n], TWINS[name][j]
                    off = 100 * (q["value"] - t) / t
                    inside = q["low"] <= t <= q["high"]
                    ok = ok and abs(off) <= 3 and inside
                    print(f"  {n:22s} {q['value']:.4f} (truth {t:g}, {off:+.1f} %), 95 % [{q['low']:.4f}, "
                          f"{q['high']:.4f}] {'covers' if inside else 'MISSES'}")
                f = c["forecast"]["closure_day"]
                covered = f["low"] <= closure <= f["high"]
                print(f"  closure: twin {closure:.3f} d, forecast {f['value']:.3f} d, band {f['low']:.3f} to "
                      f"{f['high']:.3f} d {'covers' if covered else 'MISSES'}; "
                      f"{'within 3 % and covered' if ok else 'NOT within 3 % and covered'}")
                for w in c["warnings"]:
                    print(f"  warning: {w}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
