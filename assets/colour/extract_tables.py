"""Extract the CIE tables used by diffract.colour from the colour-science package.

Run once, by hand, in a throw-away environment (the build never runs it):

    python3 -m venv /tmp/colourvenv
    /tmp/colourvenv/bin/pip install colour-science==0.4.7
    /tmp/colourvenv/bin/python -W ignore assets/colour/extract_tables.py assets/colour

Values are written with Python's repr(), i.e. the shortest decimal string that
round-trips to the same IEEE-754 double, so nothing is rounded on the way out.
"""

import sys
from pathlib import Path

import colour

out = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
version = colour.__version__


def write(name, header, columns, rows):
    lines = [f"# {h}" for h in header] + [",".join(columns)]
    lines += [",".join(repr(float(v)) for v in row) for row in rows]
    (out / name).write_text("\n".join(lines) + "\n", encoding="utf-8")


cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
write(
    "cie1931_2deg_cmf_1nm.csv",
    [
        "CIE 1931 2-degree standard observer colour-matching functions xbar, ybar, zbar.",
        f"Source: colour-science {version} (PyPI), "
        "colour.MSDS_CMFS['CIE 1931 2 Degree Standard Observer'].",
        "Original publication: CIE 015:2018 Colorimetry, 4th ed. / ISO/CIE 11664-1 "
        "(formerly CIE S 014-1), table of the CIE 1931 standard colorimetric observer;",
        "colour-science takes it from CVRL (cvrl.org, 'Older CIE Standards').",
        f"Range {cmfs.shape.start:g}..{cmfs.shape.end:g} nm, step {cmfs.shape.interval:g} nm.",
    ],
    ["lambda_nm", "xbar", "ybar", "zbar"],
    ([w, *v] for w, v in zip(cmfs.wavelengths, cmfs.values)),
)

d65 = colour.SDS_ILLUMINANTS["D65"]
# colour-science ships D65 at 5 nm over 300..780 nm only. The CIE's table runs to 830 nm; its 785..830 nm
# nodes are the CIE D-series formula (CIE 015:2018 sec. 4.1.2, S = S0 + M1 S1 + M2 S2) at D65's chromaticity,
# which colour-science implements; inside 300..780 the formula reproduces the shipped table to 5e-4.
xy_d65 = colour.temperature.CCT_to_xy_CIE_D(6500 * 1.4388 / 1.4380)
d_series = colour.sd_CIE_illuminant_D_series(xy_d65)
nodes_nm = list(range(300, 835, 5))
nodes = [d65[w] if w <= 780 else round(float(d_series[w]), 4) for w in nodes_nm]
# 1 nm by linear interpolation between the 5 nm nodes, as CIE 015:2018 (sec. 7.2.1) prescribes for D65
one_nm = range(300, 831)
values = []
for w in one_nm:
    k = min((w - 300) // 5, len(nodes_nm) - 2)
    t = (w - nodes_nm[k]) / 5.0
    values.append(nodes[k] * (1 - t) + nodes[k + 1] * t)
write(
    "cie_d65_relative_spd_1nm.csv",
    [
        "CIE standard illuminant D65, relative spectral power distribution (S(560 nm) = 100), 1 nm, 300..830 nm.",
        f"Source: colour-science {version} (PyPI): colour.SDS_ILLUMINANTS['D65'] (5 nm, 300..780 nm, from the",
        "CIE 15:2004 tables) extended to 830 nm with the CIE D-series formula at D65's chromaticity",
        "(colour.sd_CIE_illuminant_D_series(colour.temperature.CCT_to_xy_CIE_D(6500 * 1.4388 / 1.4380))),",
        "then interpolated linearly to 1 nm (CIE 015:2018 / ISO/CIE 11664-2, formerly CIE S 014-2).",
    ],
    ["lambda_nm", "relative_power"],
    ([w, v] for w, v in zip(one_nm, values)),
)
