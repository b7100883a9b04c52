#!/usr/bin/env python3
"""What the VTK files cost the main job (the single ring in sand, 120 days,
1 thread, no report): without VTK, with the wedge files only, and with the
wedge and the whole ring (the default). The files hold the particles and the
triangles between them, LZ4-compressed. Runs interleaved, five of each;
medians of CPU seconds and their ratios to the run without VTK, in one
script run, and the size of the files.

  python3 bench/vtk_cost.py
"""
import json, os, statistics, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

VARIANTS = [("no VTK", {"vtk": False, "full_ring": False}),
            ("wedge files (field_*.vtu)", {"vtk": True, "full_ring": False}),
            ("wedge and whole ring (default)", {"vtk": True, "full_ring": True})]


def run_once(work, k, output):
    with open(bench.CASE) as f:
        project = json.load(f)
    out = os.path.join(work, f"v{k}")
    project["output"] = dict(output, directory=out, report=False)
    path = os.path.join(work, f"v{k}.json")
    with open(path, "w") as f:
        json.dump(project, f)
    proc = subprocess.Popen([bench.EXE, "--threads", "1", "run", path], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, env=dict(os.environ, CI="1"))
    _, status, usage = os.wait4(proc.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"vtk_cost: run {k} failed")
    size = sum(os.path.getsize(os.path.join(out, f)) for f in os.listdir(out) if f.endswith((".vtu", ".vtp", ".pvd")))
    return usage.ru_utime + usage.ru_stime, size


def main():
    work = tempfile.mkdtemp(prefix="frostwall-vtk-")
    cpu = {k: [] for k in range(len(VARIANTS))}
    size = {}
    for _ in range(5):
        for k, (_, output) in enumerate(VARIANTS):
            c, size[k] = run_once(work, k, output)
            cpu[k].append(c)
    base = statistics.median(cpu[0])
    print("| files | CPU s (median of 5) | ratio to no VTK | VTK files (MB) |")
    print("|---|---|---|---|")
    for k, (label, _) in enumerate(VARIANTS):
        m = statistics.median(cpu[k])
        print(f"| {label} | {m:.2f} | {m / base:.2f} | {size[k] / 1e6:.1f} |")


if __name__ == "__main__":
    main()
