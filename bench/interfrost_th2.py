#!/usr/bin/env python3
"""InterFrost TH2, the frozen inclusion (Grenier et al. 2018), at 0, 3, 9
and 15 % head gradient: when the domain's coldest temperature rises above
0 C (PM1's event) at each spacing, beside the 13 codes' range and median,
with the wall time of each run on the given threads.

  python3 bench/interfrost_th2.py [--spacings 0.04,0.02,0.01,0.005]
                                  [--gradients 0,3,9,15] [--threads 2]

Runs projects/interfrost_th2_<g>.json (shipped at 1 cm) at each spacing,
without VTK or report, and prints one row per run: the thaw time, its
change from the next coarser spacing, whether it lies inside the codes'
range, the heat balance's mismatch and the run's seconds."""
import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from convergence import ROOT, run_project  # noqa: E402

# Grenier et al. (2018): the 13 codes' range and median of the time at which
# the minimum temperature rises above 0 C, hours.
ENVELOPE = {0: (32.4, 41.7, 34.7), 3: (18.1, 20.7, 18.9), 9: (10.8, 12.8, 11.8), 15: (8.6, 10.1, 9.2)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--spacings", default="0.04,0.02,0.01,0.005")
    ap.add_argument("--gradients", default="0,3,9,15")
    ap.add_argument("--threads", type=int, default=2)
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="th2-")
    print("| gradient | spacing (m) | particles | thaw (h) | change | codes' range (median) | inside | "
          "balance | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for g in [int(x) for x in args.gradients.split(",")]:
        with open(os.path.join(ROOT, "projects", f"interfrost_th2_{g}.json")) as f:
            base = json.load(f)
        lo, hi, median = ENVELOPE[g]
        previous = None
        for spacing in [float(x) for x in args.spacings.split(",")]:
            project = json.loads(json.dumps(base))
            project["numerics"]["spacing"] = spacing
            out = os.path.join(work, f"th2_{g}_{spacing}")
            project["output"] = {"directory": out, "vtk": False, "report": False}
            wall, s = run_project(project, out, args.threads)
            thaw = s["thaw_time"]
            hb = s["heat_balance"]
            flows = hb["from_boundaries"].values()
            mismatch = (hb["stored_change"] - sum(flows)) / max(abs(v) for v in flows)
            change = "" if previous is None else f"{100 * (thaw - previous) / previous:+.2f} %"
            inside = "yes" if lo <= thaw <= hi else "no"
            print(f"| {g} % | {spacing:g} | {s['run']['particles']} | {thaw:.3f} | {change} | {lo}-{hi} ({median}) | "
                  f"{inside} | {mismatch:.1e} | {wall:.1f} |", flush=True)
            previous = thaw


if __name__ == "__main__":
    main()
