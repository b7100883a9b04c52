#!/usr/bin/env python3
"""The plant's cost: the shipped shaft with its freezing plant
(projects/shaft_plant.json: two layers coupled through the brine, marched
side by side between exchanges), and the same with its plant holding a
supply of -30 C, against the same shaft without one (the layers side by
side as a study runs them, their brine held at the plant's coldest supply
behind the film the plant's brine had there). Interleaved A B A B ..., wall seconds of the
whole `frostwall run` (reports written, VTK off); the ratio is the median
of the pairs' ratios. Also each run's closure days.

  python3 bench/plant_rate.py [--repeats 3]
"""
import argparse, json, math, os, statistics, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")


def project_files(work):
    with open(os.path.join(ROOT, "projects", "shaft_plant.json")) as f:
        plant = json.load(f)
    plant["output"] = {"directory": os.path.join(work, "plant"), "vtk": False, "report": True}
    paths = {"plant": os.path.join(work, "plant.json")}
    with open(paths["plant"], "w") as f:
        json.dump(plant, f)
    return plant, paths


def run(path):
    start = time.perf_counter()
    subprocess.run([EXE, "run", path], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=dict(os.environ, CI="1"))
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-plant-")
    plant, paths = project_files(work)
    run(paths["plant"])  # warm-up; its film at the coldest supply is held without the plant
    with open(os.path.join(work, "plant", "summary.json")) as f:
        s = json.load(f)
    d = plant["pipe"]["diameter"]
    h = 1.0 / (math.pi * d * s["plant"]["films"]["R_ground"])
    without = json.loads(json.dumps(plant))
    for key in ("plant", "brine"):
        del without[key]
    without["pipe"] = {"diameter": d, "boundary": "brine", "brine_temperature": -30.0, "heat_transfer_coefficient": h}
    without["output"]["directory"] = os.path.join(work, "without")
    paths["without"] = os.path.join(work, "without.json")
    with open(paths["without"], "w") as f:
        json.dump(without, f)
    held = json.loads(json.dumps(plant))
    held["plant"] = {"supply_temperature": -30.0}
    held["output"]["directory"] = os.path.join(work, "held")
    paths["held"] = os.path.join(work, "held.json")
    with open(paths["held"], "w") as f:
        json.dump(held, f)
    names = ("plant", "held", "without")
    times = {name: [] for name in names}
    for _ in range(args.repeats):
        for name in names:
            times[name].append(run(paths[name]))
    ratios = [a / b for a, b in zip(times["plant"], times["without"])]
    held_ratios = [a / b for a, b in zip(times["held"], times["without"])]
    closure = {}
    for name in names:
        with open(os.path.join(work, name, "summary.json")) as f:
            closure[name] = [l["closure_time_days"] for l in json.load(f)["layers"]]
    print(f"film held without the plant: h = {h:.1f} W/(m2 K)")
    print("| run | wall s (median of %d) | closure per layer (d) |" % args.repeats)
    print("|---|---|---|")
    for name, label in (("plant", "with its plant (120 kW, coupled)"), ("held", "with a plant at -30 C (coupled)"),
                        ("without", "without (brine at -30 C, side by side)")):
        print(f"| {label} | {statistics.median(times[name]):.2f} | {', '.join(f'{c:.2f}' for c in closure[name])} |")
    for label, r in (("120 kW plant", ratios), ("plant at -30 C", held_ratios)):
        print(f"ratio {label} / without, median of the pairs: {statistics.median(r):.2f} "
              f"(pairs {', '.join(f'{x:.2f}' for x in r)})")


if __name__ == "__main__":
    main()
