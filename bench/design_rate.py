#!/usr/bin/env python3
"""The design features' cost: the single ring in sand (120 days, 1 thread) with the fixed
pipe wall, with brine behind a film (the wall's temperature solved at every
stage), with the wall check on the -8 degC isotherm added, and the shipped
three-layer project (three such runs side by side on the machine's cores,
wall time). CPU ratios to the fixed wall, in one script run.

  python3 bench/design_rate.py
"""
import json, os, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

BRINE = {"pipe": {"diameter": 0.127, "boundary": "brine", "brine_temperature": -20.0, "heat_transfer_coefficient": 300}}
CHECK = {"shaft": {"excavation_radius": 3.5},
         "design": {"strength": {"a": 1.0, "b": 1.0}, "pressure": {"value_MPa": 2.6}, "isotherm": -8.0}}


def main():
    work = tempfile.mkdtemp(prefix="frostwall-design-")
    rows = [("fixed wall at -20 degC (the main job)", None),
            ("brine at -20 degC, h = 300 W/(m2 K)", BRINE),
            ("brine, and the wall check on -8 degC", dict(BRINE, **CHECK))]
    print("| run (120 d, 1 thread) | steps | closure (d) | CPU s | ratio |")
    print("|---|---|---|---|---|")
    first = None
    for k, (label, extra) in enumerate(rows):
        r = bench.run(None, 1, work, f"design{k}", extra=extra)
        s = r["summary"]
        first = first or r["cpu"]
        print(f"| {label} | {s['run']['steps']} | {s['closure_time_days']:.3f} | {r['cpu']:.1f} | {r['cpu'] / first:.2f} |", flush=True)
    with open(os.path.join(os.path.dirname(bench.CASE), "shaft_layers.json")) as f:
        layered = json.load(f)
    layered["output"] = {"directory": os.path.join(work, "layers"), "vtk": False, "full_ring": False, "report": True}
    path = os.path.join(work, "layers.json")
    with open(path, "w") as f:
        json.dump(layered, f)
    start = time.perf_counter()
    subprocess.run([bench.EXE, "run", path], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=dict(os.environ, CI="1"))
    print(f"\nprojects/shaft_layers.json (3 layers side by side): {time.perf_counter() - start:.1f} s wall")


if __name__ == "__main__":
    main()
