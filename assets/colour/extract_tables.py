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
write(
    "cie_d65_relative_spd_5nm.csv",
    [
        "CIE standard illuminant D65, relative spectral power distribution (S(560 nm) = 100).",
        f"Source: colour-science {version} (PyPI), colour.SDS_ILLUMINANTS['D65'].",
        "Original publication: CIE 015:2018 Colorimetry, 4th ed. / ISO/CIE 11664-2 "
        "(formerly CIE S 014-2); colour-science takes it from the CIE 15:2004 tables.",
        f"Range {d65.shape.start:g}..{d65.shape.end:g} nm, step {d65.shape.interval:g} nm, "
        "exactly as shipped by colour-science",
        "(the CIE's official 1 nm table spans 300..830 nm; colour-science ships only this 5 nm one).",
        "diffract.colour.D65 interpolates linearly between these nodes "
        "(as CIE 15:2004 recommends for the D series) and returns 0 outside the range.",
    ],
    ["lambda_nm", "relative_power"],
    ([w, v] for w, v in zip(d65.wavelengths, d65.values)),
)
