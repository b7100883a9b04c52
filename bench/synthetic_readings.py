#!/usr/bin/env python3
"""Synthetic thermometer readings for a calibration project: frostwall runs
the project with known parameters (a twin), and its sensors are read at
regular times with Gaussian noise of a fixed seed. What `frostwall
calibrate` should then recover is known.

  bench/synthetic_readings.py projects/calibrate_single_ring.json \
      --factors conductivity=1.15 latent_heat=0.9 --noise 0.1 --every 0.5 \
      --until 20 --stop inside=14 --seed 1 -o readings.csv

The twin is `frostwall run` of the project with the twin's soil, to
--until; monitoring.csv samples the sensors 200 times over that, so
--every must be a multiple of --until / 200. --step-change sets the twin's
numerics.step_change (default: the project's).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

BUILTIN = {  # the built-in soils (lib/project/soils.cpp)
    "sand": dict(name="medium-coarse sand", density=2090, unfrozen=dict(conductivity=1.86, heat_capacity=1465.1),
                 frozen=dict(conductivity=2.56, heat_capacity=1088.4), latent_heat=52875.8, freezing_point=0.0),
}


def main():
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("project")
    a.add_argument("--factors", nargs="*", default=[], help="conductivity=F, conductivity_frozen=F, "
                   "conductivity_unfrozen=F, latent_heat=F, initial_temperature=degC")
    a.add_argument("--noise", type=float, default=0.1, help="K, standard deviation")
    a.add_argument("--every", type=float, default=0.5, help="reading interval, in the project's time unit")
    a.add_argument("--until", type=float, required=True, help="last reading time")
    a.add_argument("--stop", nargs="*", default=[], help="sensor=time: that sensor's last reading")
    a.add_argument("--seed", type=int, default=1)
    a.add_argument("--step-change", type=float, help="numerics.step_change of the twin")
    a.add_argument("--frostwall", default=os.path.join(os.path.dirname(__file__), "..", "build", "app", "frostwall"))
    a.add_argument("-o", "--output", required=True)
    args = a.parse_args()

    p = json.load(open(args.project))
    soil = p["soil"] if isinstance(p["soil"], dict) else dict(BUILTIN[p["soil"]])
    soil = json.loads(json.dumps(soil))
    for f in args.factors:
        key, value = f.split("=")
        value = float(value)
        if key in ("conductivity", "conductivity_frozen"):
            soil["frozen"]["conductivity"] *= value
        if key in ("conductivity", "conductivity_unfrozen"):
            soil["unfrozen"]["conductivity"] *= value
        if key == "latent_heat":
            soil["latent_heat"] *= value
        if key == "initial_temperature":
            p["domain"]["initial_temperature"] = value
    p["soil"] = soil
    p.pop("calibrate", None)
    if args.step_change:
        p.setdefault("numerics", {})["step_change"] = args.step_change
    p["time"] = dict(end=args.until, unit=p["time"].get("unit", "d"), snapshots=[args.until])
    with tempfile.TemporaryDirectory() as tmp:
        p["output"] = dict(directory=os.path.join(tmp, "out"), vtk=False, full_ring=False, report=False)
        twin = os.path.join(tmp, "twin.json")
        json.dump(p, open(twin, "w"), indent=1)
        subprocess.run([args.frostwall, "run", twin], check=True, stderr=subprocess.DEVNULL)
        rows = list(csv.DictReader(open(os.path.join(tmp, "out", "monitoring.csv"))))
    stop = {s.split("=")[0]: float(s.split("=")[1]) for s in args.stop}
    rng = np.random.default_rng(args.seed)
    sensors = [s["name"] for s in p["monitoring"]]
    out = ["sensor,time,temperature"]
    for s in sensors:
        for row in rows:
            t = float(row["day"])
            k = t / args.every
            if abs(k - round(k)) > 1e-6 or t > stop.get(s, args.until) + 1e-9:
                continue
            T = float(row[s + "_C"]) + rng.normal(0.0, args.noise)
            out.append(f"{s},{t:g},{T:.3f}")
    open(args.output, "w").write("\n".join(out) + "\n")
    print(f"wrote {args.output}: {len(out) - 1} readings of {len(sensors)} sensors", file=sys.stderr)


if __name__ == "__main__":
    main()
