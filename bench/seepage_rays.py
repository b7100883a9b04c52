#!/usr/bin/env python3
"""The seepage reference beside the finite-element peer, gap by gap and on the
axis rays: projects/seepage_reference.json (as shipped, 4 cm) through
`frostwall run` and the peer (../shared/peer/seepage_ring.edp) at one level,
for each flux, to day 60. Prints, per flux, each gap's closure day from both,
and the frozen wall's thickness on the downstream (0 deg, through pipe 0) and
upstream (180 deg, through pipe 13) axis rays at days 20, 40 and 60: the
length of the fully frozen interval (enthalpy at most 0) that holds the pipe,
the pipe's own diameter included, as the peer measures it.

  python3 bench/seepage_rays.py                     # 0.5 and 1 m/d, peer level 1
  python3 bench/seepage_rays.py --flux 0.5 --level 0
  python3 bench/seepage_rays.py --spacing 0.03 --no-peer   # frostwall on a finer cloud

Frostwall's interval is read from its full-ring VTK snapshots, interpolated
linearly on their triangles (vtkProbeFilter, every 2 mm); points inside the
pipe, where the cloud has no triangles, count as frozen. Needs
`apt-get install -y freefem++` and VTK's Python module (python3-vtk9, which
libvtk9-dev brings); run with /usr/bin/python3.
"""
import argparse, json, math, os, shutil, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from seepage_peer import run_peer, peer_days, frostwall_days, fmt_day, finish, CASE, EXE, PIPES  # noqa: E402

DAYS = [20, 40, 60]
RING, PIPE_RADIUS, OUTER = 5.0, 0.0635, 15.0


def run_frostwall(flux, threads, spacing, work):
    with open(CASE) as f:
        p = json.load(f)
    p["groundwater"]["darcy_flux"] = [flux, 0.0]
    if spacing:
        p["numerics"]["spacing"] = spacing
    p["time"] = {"end": 60, "unit": "d", "snapshots": DAYS}
    out = os.path.join(work, f"fw_{flux:g}")
    p["output"] = {"directory": out, "vtk": True, "full_ring": True, "report": False}
    path = os.path.join(work, f"fw_{flux:g}.json")
    with open(path, "w") as f:
        json.dump(p, f)
    subprocess.run([EXE, "--threads", str(threads), "run", path], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, env=dict(os.environ, CI="1"))
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f), out


# The reference's soil ("sand", lib/project/soils.cpp): the ring files carry
# temperature and liquid fraction, from which each particle's enthalpy (0
# when just fully frozen) is rebuilt and then interpolated, as the peer
# interpolates its nodal enthalpy.
RHO, C_FROZEN, C_UNFROZEN, LATENT = 2090.0, 1088.4, 1465.1, 52875.8


def enthalpy(T, f):
    if T < 0.0:
        return RHO * C_FROZEN * T
    if T > 0.0:
        return RHO * (LATENT + C_UNFROZEN * T)
    return RHO * LATENT * f


def ray_thickness(vtu, direction):
    """Length of the fully frozen interval holding the pipe on the axis ray
    (direction +1: downstream, through x = +5; -1: upstream)."""
    import vtk
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(vtu)
    reader.Update()
    grid = reader.GetOutput()
    T, f = grid.GetPointData().GetArray("temperature"), grid.GetPointData().GetArray("liquid_fraction")
    H = vtk.vtkDoubleArray()
    H.SetName("rebuilt_enthalpy")
    for k in range(grid.GetNumberOfPoints()):
        H.InsertNextValue(enthalpy(T.GetValue(k), f.GetValue(k)))
    grid.GetPointData().AddArray(H)
    line = vtk.vtkLineSource()
    line.SetPoint1(0.0, 0.0, 0.0)
    line.SetPoint2(direction * OUTER, 0.0, 0.0)
    n = int(OUTER / 0.002)
    line.SetResolution(n)
    probe = vtk.vtkProbeFilter()
    probe.SetInputConnection(line.GetOutputPort())
    probe.SetSourceData(grid)
    probe.Update()
    out = probe.GetOutput()
    H = out.GetPointData().GetArray("rebuilt_enthalpy")
    valid = out.GetPointData().GetArray(probe.GetValidPointMaskArrayName())
    r = [OUTER * k / n for k in range(n + 1)]
    value = []
    for k in range(n + 1):
        if abs(r[k] - RING) <= PIPE_RADIUS:
            value.append(-1.0)  # the pipe
        elif not valid.GetValue(k):
            value.append(-1.0 if abs(r[k] - RING) < 2 * PIPE_RADIUS else 1.0)  # its wall's rim; else outside
        else:
            value.append(H.GetValue(k))
    k0 = min(range(n + 1), key=lambda k: abs(r[k] - RING))

    def edge(step):
        k = k0
        while 0 <= k + step <= n and value[k + step] <= 0.0:
            k += step
        if not 0 <= k + step <= n:
            return r[k]
        a, b = value[k], value[k + step]  # a <= 0 < b: the zero between them
        return r[k] + (r[k + step] - r[k]) * (0.0 - a) / (b - a)

    return edge(1) - edge(-1)


def frostwall_rays(out):
    rays = {}
    for day in DAYS:
        vtu = os.path.join(out, f"ring_{day:04d}.vtu")
        rays[day] = (ray_thickness(vtu, -1), ray_thickness(vtu, 1))
    return rays


def peer_rays(r):
    rays = {}
    for s in r["snapshots"]:
        if round(s["day"]) in DAYS:
            full = s["full"]
            rays[round(s["day"])] = (full["upstream"]["thickness"], full["downstream"]["thickness"])
    return rays


def show(v):
    return "-" if v is None else f"{v:.3f}"


def relative(a, b):
    return "-" if a is None or b is None or b == 0 else f"{100 * (a / b - 1):+.1f} %"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--flux", type=float, nargs="*", default=[0.5, 1.0])
    ap.add_argument("--level", type=float, default=1.0)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--spacing", type=float, default=None, help="frostwall's spacing (default: as shipped)")
    ap.add_argument("--no-peer", action="store_true", help="frostwall's rays alone")
    ap.add_argument("--keep", action="store_true")
    args = ap.parse_args()
    if not args.no_peer and not shutil.which("FreeFem++-nw"):
        sys.exit("the peer needs FreeFem++: apt-get install -y freefem++")
    work = tempfile.mkdtemp(prefix="frostwall-rays-")
    for q in args.flux:
        s, out = run_frostwall(q, args.threads, args.spacing, work)
        p = None if args.no_peer else run_peer(args.level, 60, q, work)
        fw, pe = frostwall_days(s), ({} if p is None else peer_days(p))
        peer = "no peer" if p is None else f"peer level {args.level:g} ({p['vertices']} vertices)"
        print(f"\n{q:g} m/d to day 60: frostwall {s['run']['particles']} particles, {peer}\n")
        print("| gap | angle (deg) | frostwall (d) | peer (d) | frostwall - peer |")
        print("|---|---|---|---|---|")
        for k in range(PIPES // 2):
            a, b = fw.get(k), pe.get(k)
            print(f"| {k} | {(k + 0.5) * 360 / PIPES:.1f} | {fmt_day(a)} | {fmt_day(b)} | {relative(a, b)} |")
        fr, pr = frostwall_rays(out), ({} if p is None else peer_rays(p))
        print("\n| day | upstream: frostwall (m) | peer (m) | difference | downstream: frostwall (m) | peer (m) | difference |")
        print("|---|---|---|---|---|---|---|")
        for day in DAYS:
            (fu, fd), (pu, pd) = fr[day], pr.get(day, (None, None))
            print(f"| {day} | {fu:.3f} | {show(pu)} | {relative(fu, pu)} | {fd:.3f} | {show(pd)} | {relative(fd, pd)} |")
    finish(work, args.keep)


if __name__ == "__main__":
    main()
