#!/usr/bin/env python3
"""CI time as a new user meets it: a fresh clone of this repository in a
temporary folder, then the README's two commands, each timed (the Debian
packages already installed). Prints the seconds of each step and the
slowest tests of the run, from ctest's timing file.

  python3 bench/ci_time.py                 # clone, `bash .ci/main-job`, then `bash .ci/run`
  python3 bench/ci_time.py --cold          # the same with an empty compiler cache (a cache of its own)
  python3 bench/ci_time.py --ci-only       # clone, then `bash .ci/run` alone (CI's own command)
  python3 bench/ci_time.py --slowest BUILD # only the slowest tests of an existing build folder

The compiler cache (ccache) is the user's own, kept between runs on the
machine; --cold points CCACHE_DIR at an empty folder so that every source is
compiled. The clone is made from the committed state (git clone of this
repository), so commit first.
"""
import argparse, os, shutil, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def timed(command, cwd, env):
    start = time.perf_counter()
    proc = subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.perf_counter() - start
    if proc.returncode != 0:
        sys.stdout.write(proc.stdout[-6000:])
        sys.exit(f"ci_time: `{' '.join(command)}` failed with status {proc.returncode} after {seconds:.0f} s")
    return seconds, proc.stdout


def test_costs(build):
    """(seconds, name) of every test in ctest's timing file (the last run's
    time of each test: CTestCostData.txt lines are `name runs seconds`)."""
    path = os.path.join(build, "Testing", "Temporary", "CTestCostData.txt")
    costs = []
    with open(path) as f:
        for line in f:
            if line.startswith("---"):
                break
            name, _, rest = line.rstrip("\n").rpartition(" ")
            name, _, _ = name.rpartition(" ")
            try:
                costs.append((float(rest), name))
            except ValueError:
                pass
    return sorted(costs, reverse=True)


def print_slowest(build, count):
    costs = test_costs(build)
    print(f"\n{len(costs)} tests, {sum(c for c, _ in costs):.0f} s in all; the {count} slowest:")
    print("| seconds | test |\n|---|---|")
    for seconds, name in costs[:count]:
        print(f"| {seconds:.1f} | {name} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cold", action="store_true", help="an empty compiler cache of its own")
    parser.add_argument("--ci-only", action="store_true", help="only `bash .ci/run` after the clone")
    parser.add_argument("--slowest", metavar="BUILD", help="only list the slowest tests of this build folder")
    parser.add_argument("--count", type=int, default=15)
    parser.add_argument("--keep", action="store_true", help="keep the clone")
    args = parser.parse_args()
    if args.slowest:
        print_slowest(args.slowest, args.count)
        return
    work = tempfile.mkdtemp(prefix="frostwall-ci-time-")
    env = dict(os.environ, CI="true")
    if args.cold:
        env["CCACHE_DIR"] = os.path.join(work, "ccache")
    clone = os.path.join(work, "frostwall")
    start = time.perf_counter()
    subprocess.run(["git", "clone", "-q", ROOT, clone], check=True)
    rows = []
    if not args.ci_only:
        seconds, _ = timed(["bash", ".ci/main-job"], clone, env)
        rows.append(("`bash .ci/main-job` (set-up, build the program, run the main job to its report)", seconds))
    seconds, out = timed(["bash", ".ci/run"], clone, env)
    rows.append(("`bash .ci/run` (set-up, build everything, run the fast tests)", seconds))
    total = time.perf_counter() - start
    summary = [l for l in out.splitlines() if "tests passed" in l or "Total Test time" in l]
    print(f"{'cold' if args.cold else 'warm'} compiler cache, clone {clone}")
    print("| step | seconds |\n|---|---|")
    for what, s in rows:
        print(f"| {what} | {s:.0f} |")
    print(f"| from the clone to the end | {total:.0f} |")
    for line in summary:
        print(line.strip())
    print_slowest(os.path.join(clone, "build"), args.count)
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
