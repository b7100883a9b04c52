#!/usr/bin/env python3
"""Calibration from thermometers: the shipped example, timed, in one script run.

  python3 bench/calibrate.py            # projects/calibrate_single_ring.json as shipped
  python3 bench/calibrate.py --rounds 3

Runs `frostwall calibrate` on the single ring with its synthetic readings
(both conductivities x1.15, latent heat x0.9, initial temperature 15 degC,
0.1 K of noise; bench/synthetic_readings.py made them) --rounds times into
a scratch directory, and prints for each round the wall time of the
command, the fit's own time, the iterations and runs, and every parameter
against the truth with its 95 % interval; then the medians, and the true
closure day (the project run with the true parameters) against the
forecast's band.
"""
import argparse, json, os, shutil, statistics, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "frostwall")
TRUTH = {"conductivity_frozen": 1.15, "conductivity_unfrozen": 1.15, "latent_heat": 0.9, "initial_temperature": 15.0}


def main():
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("--rounds", type=int, default=1)
    args = a.parse_args()
    tmp = tempfile.mkdtemp(prefix="frostwall-bench-calibrate-")
    try:
        for f in ("calibrate_single_ring.json", "calibrate_single_ring_readings.csv"):
            shutil.copy(os.path.join(ROOT, "projects", f), tmp)
        totals, fits = [], []
        for r in range(args.rounds):
            shutil.rmtree(os.path.join(tmp, "out"), ignore_errors=True)
            start = time.perf_counter()
            subprocess.run([EXE, "calibrate", "calibrate_single_ring.json"], cwd=tmp, check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            total = time.perf_counter() - start
            c = json.load(open(os.path.join(tmp, "out", "calibrate_single_ring", "summary.json")))["calibration"]
            totals.append(total)
            fits.append(c["fit_seconds"])
            print(f"round {r + 1}: calibrate {total:.1f} s (fit {c['fit_seconds']:.1f} s, {c['iterations']} iterations, "
                  f"{c['forward_runs']} runs), rms misfit {c['rms_misfit_before']:.3f} -> {c['rms_misfit_after']:.4f} K")
            for name, q in c["parameters"].items():
                t = TRUTH[name]
                inside = q["low"] <= t <= q["high"]
                print(f"  {name:22s} {q['value']:.4f} (truth {t:g}, {100 * (q['value'] - t) / t:+.1f} %), "
                      f"95 % [{q['low']:.4f}, {q['high']:.4f}] {'covers' if inside else 'MISSES'} the truth")
            f = c["forecast"]["closure_day"]
            print(f"  closure forecast {f['value']:.2f} d, band {f['low']:.2f} to {f['high']:.2f} d")
        print(f"median: calibrate {statistics.median(totals):.1f} s, fit {statistics.median(fits):.1f} s")
        # The truth: the project with the twin's soil, as the forecast runs it.
        p = json.load(open(os.path.join(tmp, "calibrate_single_ring.json")))
        p.pop("calibrate")
        p["soil"] = dict(name="sand, true", density=2090, unfrozen=dict(conductivity=1.86 * 1.15, heat_capacity=1465.1),
                         frozen=dict(conductivity=2.56 * 1.15, heat_capacity=1088.4), latent_heat=52875.8 * 0.9,
                         freezing_point=0.0)
        p["output"] = dict(directory="truth", vtk=False, full_ring=False, report=False)
        json.dump(p, open(os.path.join(tmp, "truth.json"), "w"))
        subprocess.run([EXE, "run", "truth.json"], cwd=tmp, check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        true_closure = json.load(open(os.path.join(tmp, "truth", "summary.json")))["closure_time_days"]
        inside = f["low"] <= true_closure <= f["high"]
        print(f"true closure {true_closure:.2f} d: {'inside' if inside else 'OUTSIDE'} the band")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
