#!/usr/bin/env python3
"""Diffraction efficiencies of 1-D staircase gratings from independent rigorous solvers, for comparison with
diffract's Fourier modal method (IndependentSolverTest, docs/measurements/rigorous-crosscheck.sh).

Reads cases as JSON from a file named on the command line, or from standard input ("-" or no argument), and writes
two lines of JSON to standard output: the solvers' versions, then the results. A case:

    {"key": "sinusoid", "periodUm": 1.0, "lambdaUm": 0.5, "maxOrder": 30, "raster": 8192,
     "index": [1.56, 0.0],
     "slabs": [{"thicknessUm": 0.025, "cells": [1512, 2584]}, ...],
     "incidences": [{"key": "30", "thetaDeg": 30, "phiDeg": 0}, ...]}

Air above, the slabs top first, below them a half-space of the relief's material (complex index n + ik, k >= 0
absorbs) or of "substrateIndex" where the case has one.
A slab holds the material over the raster cells [a0, b0), [a1, b1), ... of the period's `raster` equal cells (the
cells are whole numbers so that every solver sees the same staircase). Incidence: theta from the normal, phi the
azimuth from the grating vector (x, across the grooves): the incident wave travels along (sin theta cos phi,
sin theta sin phi, -cos theta), as diffract's alpha0 = sin theta cos phi, beta = sin theta sin phi.

The result, per case key and incidence key, per solver: the efficiencies Rs, Rp, Ts, Tp of orders -M..M (order m
leaves with alpha_m = alpha0 + m lambda / period; s: the electric field perpendicular to the plane of incidence),
their sums R + T for s and p ("energy"), and the seconds it took; or "error" with the reason. The solvers:

- meent (0.13.2): the raster's exact (continuous) Fourier series, Li's rules; the 1-D TE/TM solver in the plane of
  the grating vector (phi = 0), its conical solver out of it; an absorbing substrate as a thick layer of it (see
  solve_meent), so its T is then what leaves that layer, about 0.
- nannos (2.6.5): the raster's discrete Fourier transform, the "tangent" formulation (Li's rules in 1-D).
- inkstone (0.3.15): each slab's intervals as exact boxes; Laurent's rule for every field component, so p converges
  slowly with the harmonics: a second opinion for s.

--solvers meent,nannos,inkstone picks them (default: all three); those that do not import are left out, with a
null version and the reason under "missing". --check prints the solvers' versions (null: not importable) and exits
0, or 3 when none imports.
"""
import contextlib
import json
import math
import os
import sys
import time

# BLAS threads contend for a few cores with each other and with the JVM that compares: matrices of 2M + 1 <= 81
# harmonics are quicker on one thread each
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

try:
    import numpy as np  # noqa: E402
except ImportError:  # --check still answers: every solver needs numpy, so none imports
    np = None

SOLVERS = ("meent", "nannos", "inkstone")


def versions():
    """The importable solvers and their versions."""
    found = {}
    for name in SOLVERS:
        try:
            module = __import__(name)
            found[name] = getattr(module, "__version__", None) or _distribution_version(name)
        except Exception as e:  # an import error of any kind: a broken install is as good as none
            found[name] = None
            found[name + "_error"] = "%s: %s" % (type(e).__name__, e)
    return found


def _distribution_version(name):
    try:
        from importlib.metadata import version
        return version(name)
    except Exception:
        return "unknown"


def index(case, key="index"):
    """The complex refractive index n + ik of the relief ("index") or of the substrate ("substrateIndex", by default
    the relief's)."""
    n, k = case.get(key, case["index"])
    return complex(n, k)


def intervals(slab):
    cells = slab["cells"]
    if len(cells) % 2:
        raise ValueError("a slab's cells come in pairs, got %s" % cells)
    return list(zip(cells[0::2], cells[1::2]))


def raster_row(case, slab, fill):
    """The slab's raster: `fill` (refractive index or permittivity) over its cells, 1 elsewhere."""
    row = np.ones(case["raster"], dtype=complex)
    for a, b in intervals(slab):
        row[a:b] = fill
    return row


def ordered(values, orders, m):
    """Values given for `orders` placed at -M..M (0 where an order is absent)."""
    out = [0.0] * (2 * m + 1)
    for order, v in zip(orders, values):
        if -m <= order <= m:
            out[order + m] = float(v)
    return out


def result(rs, rp, ts, tp, seconds):
    return {"Rs": rs, "Rp": rp, "Ts": ts, "Tp": tp,
            "energy": [sum(rs) + sum(ts), sum(rp) + sum(tp)], "seconds": round(seconds, 3)}


def solve_meent(case, inc):
    import meent
    m = case["maxOrder"]
    # meent's layers take an absorbing index as n - ik (its fields vary as exp(+i omega t)): given n + ik they
    # amplify, R + T > 1
    n = index(case).conjugate()
    below = index(case, "substrateIndex")
    rows = [raster_row(case, s, n) for s in case["slabs"]]
    thickness = [s["thicknessUm"] for s in case["slabs"]]
    if below.imag > 0:
        # meent 0.13.2 mishandles an absorbing half-space below: its TM admittance there is conj(kz) / N^2 where
        # conj(kz / N^2) is due (a flat interface's R_p is off Fresnel's, 0.036 for 0.026 at 1.5+0.1i and 30 degrees).
        # So the absorbing substrate becomes a layer of it so thick that the power coming back from its far side is
        # attenuated by e^-40 or more (Im kz >= k for every order), over a lossless half-space of its n.
        thickness.append(40 * case["lambdaUm"] / (8 * math.pi * below.imag))
        rows.append(np.full(case["raster"], below.conjugate()))
        below = complex(below.real, 0)
    ucell = np.stack([row.reshape(1, -1) for row in rows])
    theta = math.radians(inc["thetaDeg"])
    phi = math.radians(inc["phiDeg"])
    # phi None: the 1-D TE/TM solver (in the plane of the grating vector), far faster than the conical one
    solver = meent.call_mee(backend=0, pol=0, n_top=1, n_bot=below, theta=theta, phi=None if phi == 0 else phi,
                            fto=(m, 0), period=(case["periodUm"], 1.0), wavelength=case["lambdaUm"],
                            thickness=thickness, ucell=ucell, fourier_type=1, connecting_algo="TMM")
    out = []
    orders = list(range(-m, m + 1))
    for pol in (0, 1):  # meent's pol 0 is TE (s), 1 is TM (p); its order index i is order i - M
        solver.pol = pol
        r = solver.conv_solve().res
        out.append((ordered(np.real(np.asarray(r.de_ri)).ravel(), orders, m),
                    ordered(np.real(np.asarray(r.de_ti)).ravel(), orders, m)))
    return out[0][0], out[1][0], out[0][1], out[1][1]


def solve_nannos(case, inc):
    import nannos as nn
    m = case["maxOrder"]
    eps = index(case) ** 2
    lattice = nn.Lattice(case["periodUm"], discretization=case["raster"])
    layers = [lattice.Layer("superstrate", epsilon=1)]
    for i, s in enumerate(case["slabs"]):
        cells = intervals(s)
        fill = sum(b - a for a, b in cells)
        if fill == 0:
            layers.append(lattice.Layer("slab%d" % i, s["thicknessUm"], epsilon=1))
        elif fill == case["raster"]:
            layers.append(lattice.Layer("slab%d" % i, s["thicknessUm"], epsilon=eps))
        else:
            layers.append(lattice.Layer("slab%d" % i, s["thicknessUm"],
                                        epsilon=raster_row(case, s, eps).reshape(-1, 1)))
    layers.append(lattice.Layer("substrate", epsilon=index(case, "substrateIndex") ** 2))
    out = []
    for psi in (90, 0):  # nannos' polarisation angle: 90 degrees is s, 0 is p
        wave = nn.PlaneWave(wavelength=case["lambdaUm"], angles=(inc["thetaDeg"], inc["phiDeg"], psi))
        sim = nn.Simulation(layers, wave, nh=2 * m + 1, formulation="tangent")
        r, t = sim.diffraction_efficiencies(orders=True)
        orders = [int(h) for h in np.asarray(sim.harmonics)[0]]
        out.append((ordered(np.real(r), orders, m), ordered(np.real(t), orders, m)))
    return out[0][0], out[1][0], out[0][1], out[1][1]


def solve_inkstone(case, inc):
    import warnings
    from inkstone import Inkstone
    m = case["maxOrder"]
    n = index(case)
    period = case["periodUm"]
    raster = case["raster"]
    out = []
    for s_amp, p_amp in ((1, 0), (0, 1)):
        sim = Inkstone()
        sim.lattice = period
        sim.num_g = 2 * m + 1
        sim.frequency = 1 / case["lambdaUm"]
        sim.AddMaterial(name="material", epsilon=n * n)
        sim.AddLayer(name="in", thickness=0, material_background="vacuum")
        for i, s in enumerate(case["slabs"]):
            cells = intervals(s)
            fill = sum(b - a for a, b in cells)
            name = "slab%d" % i
            sim.AddLayer(name=name, thickness=s["thicknessUm"],
                         material_background="material" if fill == raster else "vacuum")
            if 0 < fill < raster:
                if len(cells) > 1 and cells[0][0] == 0 and cells[-1][1] == raster:
                    # the interval that wraps around the period's ends is one box
                    a, b = cells[-1][0] - raster, cells[0][1]
                    cells = [(a, b)] + cells[1:-1]
                for j, (a, b) in enumerate(cells):
                    sim.AddPattern1D(layer=name, material="material", width=(b - a) / raster * period,
                                     center=0.5 * (a + b) / raster * period, pattern_name="box%d" % j,
                                     if_gibbs_correction=False)
        sim.AddMaterial(name="substrate", epsilon=index(case, "substrateIndex") ** 2)
        sim.AddLayer(name="out", thickness=0, material_background="substrate")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sim.SetExcitation(theta=inc["thetaDeg"], phi=inc["phiDeg"], s_amplitude=s_amp, p_amplitude=p_amp)
            orders = [int(g[0]) for g in sim.pr.idx_g]
            fin, bin_ = sim.GetPowerFluxByOrder(layer="in", order=orders, z=0)
            fout, _ = sim.GetPowerFluxByOrder(layer="out", order=orders, z=0)
        fin = np.asarray(fin, dtype=float).ravel()
        incident = fin[orders.index(0)]
        r = -np.asarray(bin_, dtype=float).ravel() / incident
        t = np.asarray(fout, dtype=float).ravel() / incident
        out.append((ordered(r, orders, m), ordered(t, orders, m)))
    return out[0][0], out[1][0], out[0][1], out[1][1]


SOLVE = {"meent": solve_meent, "nannos": solve_nannos, "inkstone": solve_inkstone}


def run(cases, solvers, progress):
    results = {}
    for case in cases:
        per_case = {}
        for inc in case["incidences"]:
            per_incidence = {}
            for name in solvers:
                started = time.perf_counter()
                try:
                    rs, rp, ts, tp = SOLVE[name](case, inc)
                    per_incidence[name] = result(rs, rp, ts, tp, time.perf_counter() - started)
                except ImportError as e:
                    per_incidence[name] = {"error": "not installed: %s" % e}
                except Exception as e:  # one solver's failure is a result, not the end of the run
                    per_incidence[name] = {"error": "%s: %s" % (type(e).__name__, e)}
                if progress:
                    print("%s %s %s: %s" % (case["key"], inc["key"], name,
                                            per_incidence[name].get("error")
                                            or "%.1f s" % per_incidence[name]["seconds"]), file=sys.stderr)
            per_case[inc["key"]] = per_incidence
        results[case["key"]] = per_case
    return results


def main(argv):
    import argparse
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cases", nargs="?", default="-", help="the cases' JSON file ('-' or none: standard input)")
    parser.add_argument("--solvers", default=",".join(SOLVERS),
                        help="comma-separated, of " + ", ".join(SOLVERS) + " (default: all of them)")
    parser.add_argument("--check", action="store_true", help="print the importable solvers' versions and exit")
    parser.add_argument("--progress", action="store_true", help="a line per result on standard error")
    args = parser.parse_args(argv)
    # what the solvers print goes to standard error: standard output carries the JSON alone
    with contextlib.redirect_stdout(sys.stderr):
        found = versions()
    if args.check:
        print(json.dumps(found))
        return 0 if any(found[s] for s in SOLVERS) else 3
    asked = [s.strip() for s in args.solvers.split(",") if s.strip()]
    unknown = [s for s in asked if s not in SOLVERS]
    if unknown:
        print("rigorous_crosscheck: unknown solver %s: --solvers takes %s" % (", ".join(unknown), ", ".join(SOLVERS)),
              file=sys.stderr)
        return 2
    try:
        text = sys.stdin.read() if args.cases == "-" else open(args.cases).read()
        document = json.loads(text)
    except (OSError, ValueError) as e:
        print("rigorous_crosscheck: cannot read the cases %s: %s" % (args.cases, e), file=sys.stderr)
        return 2
    cases = document["cases"] if isinstance(document, dict) else document
    # first line: what imports (a solver that does not is left out, its version null and "missing" saying why), so
    # that a caller can give up before the solving; second line: the results
    print(json.dumps({"versions": {s: found[s] for s in SOLVERS},
                      "missing": {s: found[s + "_error"] for s in SOLVERS if not found[s]}}), flush=True)
    try:
        with contextlib.redirect_stdout(sys.stderr):
            results = run(cases, [s for s in asked if found[s]], args.progress)
    except KeyError as e:
        print("rigorous_crosscheck: a case or incidence in %s lacks the key %s" % (args.cases, e), file=sys.stderr)
        return 2
    print(json.dumps({"results": results}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
