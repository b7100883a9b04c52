"""Runs a FreeFem++ peer script (bench/peer/, ../shared/peer/) on one core."""
import json, os, subprocess, time


def run_freefem(script, options, out, cwd):
    """FreeFem++-nw `script` with `options` (a list of strings) writing the JSON
    `out`: that JSON, with the script's wall time added as script_wall_s."""
    start = time.perf_counter()
    subprocess.run(["FreeFem++-nw", script, "-v", "0", *options, "-out", out], check=True, cwd=cwd,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=dict(os.environ, OMP_NUM_THREADS="1"))
    wall = time.perf_counter() - start
    with open(out) as f:
        r = json.load(f)
    r["script_wall_s"] = wall
    return r
