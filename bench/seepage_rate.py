#!/usr/bin/env python3
"""Issue 17's speed target: the single ring in sand at 1 m/d of seepage against
still water, CPU seconds on one thread over the first `--days` (0.5 by default:
the full 120 days under seepage take more than an hour). Four rows in one script
run: still water on its wedge (the product's run), still water on the full ring
(numerics.symmetry off: the cloud the flow needs is half of it), and the
seepage run on its half section with the default coupled step and with the
explicit limited scheme (held to the advective Courant limit). The ratios
compare the same simulated days (set-up included).

  python3 bench/seepage_rate.py [--days 0.5]
"""
import argparse, os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402

WATER = {"groundwater": {"hydraulic_conductivity": 1e-4, "porosity": 0.35, "darcy_flux": [1.0, 0.0], "unit": "m/d"}}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--days", type=float, default=0.5)
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="frostwall-seepage-")
    span = {"end": args.days, "unit": "d", "snapshots": [args.days]}
    rows = [("still water, wedge (the product's run)", None, None),
            ("still water, full ring (symmetry off)", {"symmetry": "off"}, None),
            ("1 m/d, half section, coupled step (default)", None, WATER),
            ("1 m/d, half section, explicit limited", None,
             {"groundwater": dict(WATER["groundwater"], advection="limited")})]
    print(f"| run (first {args.days:g} d, 1 thread) | particles | steps | flow solves | CPU s | ratio to the wedge | ratio to the full ring |")
    print("|---|---|---|---|---|---|---|")
    first = ring = None
    for k, (label, numerics, extra) in enumerate(rows):
        r = bench.run(numerics, 1, work, f"seepage{k}", time_settings=span, extra=extra)
        s = r["summary"]
        first = first or r["cpu"]
        ring = r["cpu"] if k == 1 else ring
        solves = s.get("groundwater", {}).get("flow_solves", "")
        to_ring = f"{r['cpu'] / ring:.2f}" if ring else ""
        print(f"| {label} | {s['run']['particles']} | {s['run']['steps']} | {solves} | {r['cpu']:.1f} | {r['cpu'] / first:.0f} | {to_ring} |",
              flush=True)


if __name__ == "__main__":
    main()
