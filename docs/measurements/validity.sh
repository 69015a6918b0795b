#!/usr/bin/env bash
# Regenerates the validity map, docs/measurements/validity.md and docs/images/validity-*.png, and the table the commands' warnings
# read, assets/validity/scalar-validity.csv, from the repository root: bash docs/measurements/validity.sh
# 360 cases (3 relief shapes x 8 periods x 5 depths x 3 light angles), each a rigorous solve at 21 wavelengths and
# three rows of BRDF maps; about 70 minutes on 2 busy cores. The run writes out/validity/validity.csv after every case and reads
# it back, so an interrupted run goes on where it stopped; the rigorous orders are also kept in the disk cache.
set -euo pipefail
cd "$(dirname "$0")/../.."
./diffract validity -o out/validity
mkdir -p docs/images assets/validity
sed "s#](images/#](../images/#g" out/validity/validity.md > docs/measurements/validity.md   # its pictures are in docs/images/
cp out/validity/images/validity-*.png docs/images/
cp out/validity/validity.csv assets/validity/scalar-validity.csv
