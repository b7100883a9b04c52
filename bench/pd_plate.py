#!/usr/bin/env python3
"""The PD paper's plate at its own resolution (0.1 mm, 10 000 particles) to
200 s through `frostwall run`, on 2 and on 1 thread (wall time, relaxations,
ADR iterations), then the bond-update rates (build/bench/pd_plate_rate).

  python3 bench/pd_plate.py            # about a minute
"""
import json, os, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
RATE = os.path.join(ROOT, "build", "bench", "pd_plate_rate")


def main():
    work = tempfile.mkdtemp(prefix="frostwall-pd-bench-")
    with open(os.path.join(ROOT, "projects", "plate_cooling.json")) as f:
        project = json.load(f)
    project["time"] = {"end": 200, "unit": "s", "snapshots": [50, 100, 200]}
    for threads in (2, 1):
        project["output"] = {"directory": os.path.join(work, f"t{threads}"), "vtk": False, "report": False}
        path = os.path.join(work, f"plate_t{threads}.json")
        with open(path, "w") as f:
            json.dump(project, f)
        start = time.perf_counter()
        subprocess.run([EXE, "--threads", str(threads), "run", path], check=True, stderr=subprocess.DEVNULL,
                       env=dict(os.environ, CI="1"))
        wall = time.perf_counter() - start
        with open(os.path.join(work, f"t{threads}", "summary.json")) as f:
            s = json.load(f)
        mech = s["run"]["mechanics"]
        a = {r[0]: (r[1] ** 2 + r[2] ** 2) ** 0.5 for r in s["monitoring_solid"]["A"]}
        print(f"plate to 200 s, {threads} thread{'s' if threads > 1 else ''}: {wall:.1f} s wall; "
              f"{s['run']['particles']} particles, {s['run']['steps']} thermal steps, {mech['relaxations']} relaxations, "
              f"{mech['relaxation_iterations']} ADR iterations (longest {mech['longest_relaxation']}); "
              f"|u(A)| at 50 / 100 / 200 s: {a[50.0]:.4e} / {a[100.0]:.4e} / {a[200.0]:.4e} m", flush=True)
    if os.path.exists(RATE):
        subprocess.run([RATE], check=True)


if __name__ == "__main__":
    main()
