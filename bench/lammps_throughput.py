#!/usr/bin/env python3
"""LAMMPS's own throughput on this machine against frostwall's coupled run.

Replays a CFD-DEM run's grain assembly (its dem_commands.txt: the same
grains, pair style, walls, neighbour settings and step) in Debian's `lmp`
executable without the water (fix external needs frostwall's callback, so
it is removed), for a fixed number of steps on the same ranks, and reads
LAMMPS's `Loop time`. Prints atom-steps per second (and per core) for
plain LAMMPS and for the frostwall run (its dem_steps x grains over
run_wall_time_s): how close the coupled run is to the contact
computation's own limit.

  python3 bench/lammps_throughput.py RUN_DIR            # a finished run's output folder
  python3 bench/lammps_throughput.py RUN_DIR --steps 2000 --ranks 2

RUN_DIR is run from its parent's working directory, as dem_commands.txt
names its files from there (the packing cache is an absolute path).
"""
import argparse, json, os, re, subprocess, tempfile


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_dir")
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--ranks", type=int, default=2)
    args = parser.parse_args()
    run_dir = os.path.abspath(args.run_dir)
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(run_dir, "dem_commands.txt")) as f:
        commands = [line for line in f if not line.startswith("#")]
    commands += ["unfix fluid\n", "thermo 1000\n", f"run {args.steps}\n"]
    with tempfile.TemporaryDirectory() as work:
        script = os.path.join(work, "in.throughput")
        with open(script, "w") as f:
            f.writelines(commands)
        out = subprocess.run(["mpirun", "--allow-run-as-root", "-np", str(args.ranks), "lmp", "-in", script,
                              "-log", os.path.join(work, "log.lammps")], cwd=os.path.dirname(run_dir),
                             capture_output=True, text=True, check=True).stdout
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", out)
    seconds, procs, steps, atoms = loops[-1]
    lammps_rate = int(steps) * int(atoms) / float(seconds)
    ours = summary["dem_steps"] * summary["grains"] / summary["run_wall_time_s"]
    print(f"| run | ranks | atom-steps/s | per core |")
    print(f"|---|---|---|---|")
    print(f"| LAMMPS alone ({steps} steps, {atoms} grains) | {procs} | {lammps_rate:.3g} | "
          f"{lammps_rate / int(procs):.3g} |")
    print(f"| frostwall, coupled ({summary['dem_steps']} steps, {summary['grains']} grains) | "
          f"{summary['ranks']} | {ours:.3g} | {ours / summary['ranks']:.3g} |")
    print(f"\nfrostwall runs at {ours / lammps_rate:.2f} of LAMMPS's own rate; at LAMMPS's rate the run's "
          f"{summary['dem_steps']} steps would take {summary['dem_steps'] * summary['grains'] / lammps_rate:.0f} s "
          f"against {summary['run_wall_time_s']:.0f} s.")


if __name__ == "__main__":
    main()
