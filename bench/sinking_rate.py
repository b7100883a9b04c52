#!/usr/bin/env python3
"""The excavation's cost: the shipped sinking shaft (projects/shaft_sinking.json:
the shaft with its plant, each layer dug on its day, lined three days later)
against the same project without `excavation`, over the same days.
Interleaved A B A B ..., wall seconds of the whole `frostwall run` (reports
written, VTK off); the ratio is the median of the pairs' ratios. Also each
run's steps and RKL2 stages per layer, and the sinking's critical section.

  python3 bench/sinking_rate.py [--repeats 3]
"""
import argparse, json, os, statistics, tempfile

from plant_rate import ROOT, run  # one `frostwall run`, timed


def write(work, name, project):
    project["output"] = {"directory": os.path.join(work, name), "vtk": False, "report": True}
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(project, f)
    return path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-sinking-")
    with open(os.path.join(ROOT, "projects", "shaft_sinking.json")) as f:
        sinking = json.load(f)
    kept = json.loads(json.dumps(sinking))
    del kept["excavation"]
    paths = {"sinking": write(work, "sinking", sinking), "kept": write(work, "kept", kept)}
    run(paths["sinking"])  # warm-up
    times = {name: [] for name in paths}
    for _ in range(args.repeats):
        for name in paths:
            times[name].append(run(paths[name]))
    ratios = [a / b for a, b in zip(times["sinking"], times["kept"])]
    print("| run | wall s (median of %d) | steps per layer | RKL2 stages per layer |" % args.repeats)
    print("|---|---|---|---|")
    for name, label in (("sinking", "with the excavation"), ("kept", "without")):
        with open(os.path.join(work, name, "summary.json")) as f:
            s = json.load(f)
        steps = ", ".join(str(l["run"]["steps"]) for l in s["layers"])
        stages = ", ".join(str(l["run"].get("stages")) for l in s["layers"])
        print(f"| {label} | {statistics.median(times[name]):.2f} | {steps} | {stages} |")
        if name == "sinking":
            e = s["excavation"]
            critical = (e["critical_section"], e["critical_depth"], e["critical_day"], e["margin_min"])
    print(f"ratio with / without, median of the pairs: {statistics.median(ratios):.2f} "
          f"(pairs {', '.join(f'{x:.2f}' for x in ratios)})")
    print("critical section %s at %.1f m, day %.1f, smallest margin %.3f m" % critical)


if __name__ == "__main__":
    main()
