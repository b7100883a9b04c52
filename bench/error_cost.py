#!/usr/bin/env python3
"""What the error estimate (numerics.error_estimate: three coarser twins at
1.35, 1.5 and 1.65 times the spacing) costs: the main job (the single ring
in sand, 120 days, 1 thread, no VTK, no report) without and with it, runs
interleaved, five of each, medians of CPU seconds and their ratio, in one
script run; then the shipped layout study (4 variants, 2 at a time, VTK
and report as shipped) once without and once with the estimate (a study
turns it on; the patch turns it off), wall seconds.

  python3 bench/error_cost.py            # both
  python3 bench/error_cost.py --main     # the main job only
"""
import json, os, statistics, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_main(work, estimate):
    # bench.run: the main job with these numerics (the case has none of its own), no VTK, no report.
    return bench.run({"error_estimate": estimate}, 1, work, f"main_{estimate}")["cpu"]


def run_study(work, estimate):
    with open(os.path.join(ROOT, "projects", "study_layouts.json")) as f:
        study = json.load(f)
    study["base"] = os.path.join(ROOT, "projects", study["base"])
    study["output"]["directory"] = os.path.join(work, f"study_{estimate}")
    study["patch"] = {"numerics": {"error_estimate": estimate}}
    path = os.path.join(work, f"study_{estimate}.json")
    with open(path, "w") as f:
        json.dump(study, f)
    start = time.monotonic()
    subprocess.run([bench.EXE, "study", path], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   cwd=os.path.join(ROOT, "projects"), env=dict(os.environ, CI="1"))
    return time.monotonic() - start


def main():
    work = tempfile.mkdtemp(prefix="frostwall-error-cost-")
    cpu = {False: [], True: []}
    for _ in range(5):
        for estimate in (False, True):
            cpu[estimate].append(run_main(work, estimate))
    off, on = statistics.median(cpu[False]), statistics.median(cpu[True])
    print("| main job, 1 thread | CPU s (median of 5) | ratio |")
    print("|---|---|---|")
    print(f"| without the estimate | {off:.2f} | 1.00 |")
    print(f"| with the estimate (run + 3 twins) | {on:.2f} | {on / off:.2f} |")
    print(f"\nthe twins cost {100 * (on - off) / off:.0f} % of the run")
    sys.stdout.flush()
    if "--main" in sys.argv:
        return
    off, on = run_study(work, False), run_study(work, True)
    print("\n| layout study (4 variants, 2 at a time) | wall s | ratio |")
    print("|---|---|---|")
    print(f"| without the estimate | {off:.1f} | 1.00 |")
    print(f"| with the estimate | {on:.1f} | {on / off:.2f} |")


if __name__ == "__main__":
    main()
