#!/usr/bin/env python3
"""The 2-D Fourier modal method's cross-check: solves the cells of a JSON file with meent 0.13.2 and prints one JSON
line per case with the reflected orders' unpolarised efficiencies.

Input (the file named on the command line): a list of cases, each
  {"key", "periodXUm", "periodYUm", "cols", "rows", "index": [n, k], "lambdaUm", "maxOrder",
   "slabs": [{"thicknessUm", "mask": [0/1 row-major, rows x cols]}], "incidences": [{"thetaDeg", "phiDeg"}]}.
Output: first line {"versions": {"meent": version or null}, "missing": reason}; then one line
  {"results": {key: {"thetaDeg_phiDeg": {"laurent": R[q][p], "li": R[q][p]}}}}
with R the mean of the TE and TM runs' reflected efficiencies, rows q = -M..M, columns p = -M..M.

meent's exact (continuous) Fourier series of the raster (fourier_type 1) takes Li's rules for crossed gratings
(the inverse rule along one axis for E_x and E_y); "laurent" solves again with its own Laurent coefficients for every
component (its cfs2d asked for the plain series in both directions), the formulation diffract's cell solver uses.
"""
import json
import math
import os
import sys

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")


def main():
    try:
        import numpy as np
        import meent
        from meent.on_numpy.emsolver import convolution_matrix as cm
        version = getattr(meent, "__version__", None)
        if version is None:
            from importlib.metadata import version as v
            version = v("meent")
    except Exception as e:  # any import error: no solver
        print(json.dumps({"versions": {"meent": None}, "missing": "%s: %s" % (type(e).__name__, e)}), flush=True)
        return 0
    print(json.dumps({"versions": {"meent": version}}), flush=True)
    with open(sys.argv[1]) as f:
        cases = json.load(f)
    results = {}
    original = cm.cfs2d

    def laurent(eps, xs, ys, a, b, fx, fy, t):
        return original(eps, xs, ys, 1, 1, fx, fy, t)

    for case in cases:
        n = complex(*case["index"])
        ucell = np.stack([np.where(np.asarray(s["mask"]).reshape(case["rows"], case["cols"]) > 0, n.conjugate(), 1)
                          .astype(complex) for s in case["slabs"]])
        thickness = [s["thicknessUm"] for s in case["slabs"]]
        m = case["maxOrder"]
        per_case = {}
        for inc in case["incidences"]:
            out = {}
            for name, conv in (("laurent", laurent), ("li", original)):
                cm.cfs2d = conv
                try:
                    total = 0
                    for pol in (0, 1):
                        s = meent.call_mee(backend=0, pol=pol, n_top=1, n_bot=n.conjugate(),
                                           theta=math.radians(inc["thetaDeg"]), phi=math.radians(inc["phiDeg"]),
                                           fto=(m, m), period=(case["periodXUm"], case["periodYUm"]),
                                           wavelength=case["lambdaUm"], thickness=thickness, ucell=ucell,
                                           fourier_type=1, connecting_algo="TMM")
                        total = total + np.real(np.asarray(s.conv_solve().res.de_ri))
                finally:
                    cm.cfs2d = original
                out[name] = (0.5 * total).tolist()
            per_case["%s_%s" % (inc["thetaDeg"], inc["phiDeg"])] = out
        results[case["key"]] = per_case
    print(json.dumps({"results": results}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
