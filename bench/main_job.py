#!/usr/bin/env python3
"""The main job's wall time as a user runs it: `frostwall --threads 2 run
projects/single_ring_sand.json` (VTK of the wedge and the whole ring,
summary.json, CSV and report.html), its output in a temporary directory.
Builds nothing. Given a second executable (e.g. a copy of an earlier
build), runs the two in turn, A B A B ..., and prints each one's median
wall and CPU seconds and the median of the pairwise ratios B/A; the
summary.json of both is compared, the timing fields left out.

  python3 bench/main_job.py                          # build/app/frostwall, 5 runs
  python3 bench/main_job.py OLD/frostwall            # against another build (a copy of an earlier one)
  python3 bench/main_job.py --repeats 9 --threads 1 OTHER
"""
import argparse, json, os, shutil, statistics, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
CASE = os.path.join(ROOT, "projects", "single_ring_sand.json")
TIMING_KEYS = {"wall_seconds", "coarse_seconds"}


def run_once(exe, threads, work):
    """One main job in a fresh directory under `work`; returns wall s, CPU s
    and the summary.json written."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    start = time.perf_counter()
    proc = subprocess.Popen([exe, "--threads", str(threads), "run", CASE], cwd=work, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, env=dict(os.environ, CI="1"))
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    err = proc.stderr.read().decode(errors="replace")
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"main_job: {exe} failed:\n{err}")
    with open(CASE) as f:
        out = os.path.join(work, json.load(f)["output"]["directory"])
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    return wall, usage.ru_utime + usage.ru_stime, summary


def without_timing(value):
    if isinstance(value, dict):
        return {k: without_timing(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [without_timing(v) for v in value]
    return value


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("other", nargs="?", help="a second executable, run in turn with build/app/frostwall")
    parser.add_argument("--exe", default=EXE, help="the executable measured (default build/app/frostwall)")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    exes = [os.path.abspath(args.exe)] + ([os.path.abspath(args.other)] if args.other else [])
    root = tempfile.mkdtemp(prefix="frostwall-main-job-")
    wall = {e: [] for e in exes}
    cpu = {e: [] for e in exes}
    summaries = {}
    try:
        for e in exes:  # a warm-up each: the page cache, the first run's libraries
            run_once(e, args.threads, os.path.join(root, "warm"))
        for _ in range(args.repeats):
            for k, e in enumerate(exes):
                w, c, summaries[e] = run_once(e, args.threads, os.path.join(root, f"run{k}"))
                wall[e].append(w)
                cpu[e].append(c)
    finally:
        shutil.rmtree(root, ignore_errors=True)
    print(f"main job, {args.threads} threads, {args.repeats} interleaved runs each, medians:")
    for e in exes:
        print(f"  {e}: wall {statistics.median(wall[e]):.3f} s (min {min(wall[e]):.3f}, max {max(wall[e]):.3f}),"
              f" CPU {statistics.median(cpu[e]):.3f} s")
    if len(exes) == 2:
        a, b = exes
        ratio = statistics.median(wb / wa for wa, wb in zip(wall[a], wall[b]))
        cpu_ratio = statistics.median(cb / ca for ca, cb in zip(cpu[a], cpu[b]))
        print(f"  ratio {os.path.basename(b)} / {os.path.basename(a)}: wall {ratio:.2f}x, CPU {cpu_ratio:.2f}x")
        same = without_timing(summaries[a]) == without_timing(summaries[b])
        print(f"  summary.json (timing fields left out): {'the same' if same else 'DIFFERENT'}")


if __name__ == "__main__":
    main()
