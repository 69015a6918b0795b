#!/usr/bin/env bash
# Times a reference BRDF map computed whole, by `submit --local 1 --piece-count 1` (the whole map as one worker), and by
# `submit --local J` (J = 1 and 2, 8 pieces each), checks that all write the same bytes, and splits each piece's time
# into its fixed cost (Java start, loading the patch and building the BRDF) and its work (the pixels). Where a Slurm
# answers (sinfo; bash .ci/slurm-node starts a one-node one here), also times the pieces as a job array
# (`submit --slurm`) and shows the job script it writes. Profiles one piece with Java's flight recorder (where its work
# goes), and splits a small bench sweep into pieces (merged rows against the single run's).
# Writes docs/measurements/pieces.md. SIZE=64 bash docs/measurements/pieces.sh for a quicker run.
set -euo pipefail
cd "$(dirname "$0")/../.."
SIZE=${SIZE:-256}
PIECES=${PIECES:-8}
MAP=(--patch assets/patches/elaphe-100px.gwy --theta-i 30 --size "$SIZE" --exposure auto)
./diffract --version > /dev/null  # builds the jar first, outside the timings
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
seconds() {  # command...: runs it, output to $out/log.txt, and prints its wall time in seconds
    local start end
    start=$(date +%s.%N)
    "$@" > "$out/log.txt" 2>&1
    end=$(date +%s.%N)
    printf '%.1f' "$(echo "$end - $start" | bc)"
}
# the whole map first: it also fills the disk cache, as the runs that follow find it
whole=$(seconds ./diffract brdfmap "${MAP[@]}" -o "$out/whole.png" --pfm "$out/whole.pfm")
one=$(seconds ./diffract submit --local 1 --piece-count 1 -- brdfmap "${MAP[@]}" -o "$out/one.png" --pfm "$out/one.pfm")
cp "$out/log.txt" "$out/one.log"
local1=$(seconds ./diffract submit --local 1 --piece-count "$PIECES" -- brdfmap "${MAP[@]}" -o "$out/l1.png" --pfm "$out/l1.pfm")
cp "$out/log.txt" "$out/l1.log"
local2=$(seconds ./diffract submit --local 2 --piece-count "$PIECES" -- brdfmap "${MAP[@]}" -o "$out/l2.png" --pfm "$out/l2.pfm")
cp "$out/log.txt" "$out/l2.log"
# the same two with one processor per worker: what a second worker adds when each has a core of its own
local1c=$(seconds ./diffract submit --local 1 --piece-count "$PIECES" --cpus-per-task 1 -- brdfmap "${MAP[@]}" -o "$out/l1c.png" --pfm "$out/l1c.pfm")
cp "$out/log.txt" "$out/l1c.log"
local2c=$(seconds ./diffract submit --local 2 --piece-count "$PIECES" --cpus-per-task 1 -- brdfmap "${MAP[@]}" -o "$out/l2c.png" --pfm "$out/l2c.pfm")
cp "$out/log.txt" "$out/l2c.log"
runs=(one l1 l2 l1c l2c)
# where one piece's time goes: the flight recorder's samples of piece 3 (one processor), by the method on top of the
# stack; the exact spectrum's phase-centre expansions (ExactSpectrum.expand, .bounds) anywhere on it; and the time the
# Java compiler took (-XX:+CITime)
java -XX:StartFlightRecording=filename="$out/piece.jfr",settings=profile -XX:+CITime -Xlog:disable \
    -Djava.awt.headless=true -XX:ActiveProcessorCount=1 -cp target/diffract.jar diffract.app.Main brdfmap "${MAP[@]}" \
    --tile 3/"$PIECES" --pieces "$out/jfr" --quiet > "$out/jfr.log" 2>&1
profiled_work=$(sed -nE 's/.*work ([0-9.]+) s.*/\1/p' "$out/jfr.log")
compiler=$(sed -nE 's/^ *Total compilation time *: *([0-9.]+) s.*/\1/p' "$out/jfr.log")
# the same piece compiled by the first tier alone (less compilation, slower code)
c1_work=$(java -XX:TieredStopAtLevel=1 -Xlog:disable -Djava.awt.headless=true -XX:ActiveProcessorCount=1 \
    -cp target/diffract.jar diffract.app.Main brdfmap "${MAP[@]}" --tile 3/"$PIECES" --pieces "$out/c1" --quiet 2>&1 \
    | sed -nE 's/.*work ([0-9.]+) s.*/\1/p')
jfr print --events jdk.ExecutionSample "$out/piece.jfr" > "$out/samples.txt"
samples=$(grep -c 'jdk.ExecutionSample' "$out/samples.txt")
expansions=$(awk '/jdk.ExecutionSample/ { n++ } /ExactSpectrum\.(expand|bounds)/ { hit[n] = 1 } END { print length(hit) }' \
    "$out/samples.txt")
top=$(grep -A1 'stackTrace = \[' "$out/samples.txt" | grep -v -e 'stackTrace' -e '^--' | sed -E 's/^ *//; s/\(.*//' \
    | sort | uniq -c | sort -rn | head -4 | awk '{ printf "%s`%s` %d", (NR > 1 ? ", " : ""), $2, $1 }')
# a small bench sweep whole and in two pieces by two workers: the same rows but for the GPU times (measured again)
# and the Pareto column that follows from them
SWEEP=(--patches blazed --variants flss,nmm --terms 4,8 --lambda-steps 25 --window-radii 1 --texture-formats rg32f --size 24)
bench_same=""
if ./diffract bench "${SWEEP[@]}" -o "$out/bench-whole" --quiet > "$out/bench.log" 2>&1 \
    && ./diffract submit --local 2 -- bench "${SWEEP[@]}" -o "$out/bench-split" --quiet >> "$out/bench.log" 2>&1; then
    mask() { cut -d, -f1-8,10-14,16- "$1"; }
    if cmp -s <(mask "$out/bench-whole/results.csv") <(mask "$out/bench-split/results.csv"); then
        bench_same=yes
    else
        bench_same=NO
    fi
fi
if sinfo -h -o %T 2>/dev/null | grep -qE '^(idle|mixed)$'; then
    slurm=$(seconds ./diffract submit --slurm --piece-count "$PIECES" --cpus-per-task 1 --keep-pieces "$out/slurm" \
        -- brdfmap "${MAP[@]}" -o "$out/s.png" --pfm "$out/s.pfm")
    cp "$out/log.txt" "$out/s.log"
    runs+=(s)
fi
# the Open Job Description template of the same pieces, run on this machine where openjd-cli is installed
openjd_same=""
if command -v openjd >/dev/null 2>&1; then
    if openjd check docs/guide/openjd/brdfmap-pieces.yaml > "$out/openjd.log" 2>&1 \
        && openjd run docs/guide/openjd/brdfmap-pieces.yaml --step Merge --run-dependencies -p Diffract="$PWD/diffract" \
            -p WorkDir="$PWD" -p "MapOptions=${MAP[*]}" -p PieceCount="$PIECES" -p PiecesDir="$out/openjd" \
            -p Output="$out/o.png" >> "$out/openjd.log" 2>&1 \
        && cmp -s "$out/whole.png" "$out/o.png"; then
        openjd_same=yes
    else
        openjd_same=NO
    fi
fi
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
same=yes
for run in "${runs[@]}"; do
    cmp -s "$out/whole.png" "$out/$run.png" && cmp -s "$out/whole.pfm" "$out/$run.pfm" || same=NO
done
# "piece I/N (rows A..B) finished in W s (start S s, setup U s, work K s); ..." -> I|A..B|W|S|U|K
pieces() {  # sorted as join wants them
    sed -nE 's#^piece ([0-9]+)/[0-9]+ \(rows ([0-9.]+)\) finished in ([0-9.]+) s \(start ([0-9.]+) s, setup ([0-9.]+) s, work ([0-9.]+) s\).*#\1|\2|\3|\4|\5|\6#p' "$1" | sort -t'|' -k1,1
}
sum() {  # column of pieces(): the sum
    pieces "$1" | awk -F'|' -v c="$2" '{ s += $c } END { printf "%.1f", s }'
}
fixed() {  # the pieces' fixed cost (start and setup) as a percentage of their work: of the sums, and the largest
    pieces "$1" | awk -F'|' '{ f = $4 + $5; s += f; w += $6; r = 100 * f / $6; if (r > m) m = r }
        END { printf "%.1f (up to %.1f)", 100 * s / w, m }'
}
{
    echo "# A reference map in pieces, timed"
    echo
    echo "Generated by \`bash docs/measurements/pieces.sh\` (SIZE=$SIZE, $PIECES pieces) on $(nproc) cores, load average $load_before"
    echo "before and $load_after after (after: this script's own runs included; the machine is shared, and the wall times move"
    echo "with its load). The map:"
    echo "\`brdfmap ${MAP[*]}\`, the reference on the CPU. Outputs of the ${#runs[@]} runs identical byte for byte: **$same**."
    if awk -v a="${load_before%% *}" 'BEGIN { exit !(a > 1) }'; then
        echo
        echo "**The machine was busy with other work when this run began** (a load average above 1 on 2 cores): the wall"
        echo "times, and the ratios between runs made minutes apart, measure that work's changing share of the"
        echo "processors as much as the pieces. The per-piece split of each run (start, setup, work) holds."
    fi
    echo
    echo "| run | wall time (s) | sum of the pieces' start (s) | ... setup (s) | ... work (s) | fixed cost: (start + setup) / work (%) |"
    echo "| --- | ---: | ---: | ---: | ---: | ---: |"
    echo "| brdfmap alone | $whole | | | | |"
    echo "| submit --local 1 --piece-count 1 | $one | $(sum "$out/one.log" 4) | $(sum "$out/one.log" 5) | $(sum "$out/one.log" 6) | $(fixed "$out/one.log") |"
    echo "| submit --local 1 --piece-count $PIECES | $local1 | $(sum "$out/l1.log" 4) | $(sum "$out/l1.log" 5) | $(sum "$out/l1.log" 6) | $(fixed "$out/l1.log") |"
    echo "| submit --local 2 --piece-count $PIECES | $local2 | $(sum "$out/l2.log" 4) | $(sum "$out/l2.log" 5) | $(sum "$out/l2.log" 6) | $(fixed "$out/l2.log") |"
    echo "| submit --local 1 --piece-count $PIECES --cpus-per-task 1 | $local1c | $(sum "$out/l1c.log" 4) | $(sum "$out/l1c.log" 5) | $(sum "$out/l1c.log" 6) | $(fixed "$out/l1c.log") |"
    echo "| submit --local 2 --piece-count $PIECES --cpus-per-task 1 | $local2c | $(sum "$out/l2c.log" 4) | $(sum "$out/l2c.log" 5) | $(sum "$out/l2c.log" 6) | $(fixed "$out/l2c.log") |"
    if [ -n "${slurm:-}" ]; then
        echo "| submit --slurm --piece-count $PIECES --cpus-per-task 1 (one-node Slurm, $(nproc) CPUs) | $slurm | | | | |"
    fi
    echo
    echo "Each of \`submit --local\`'s J workers is one Java process that computes piece after piece, as they come:"
    echo "a map's outer bands first (0, $((PIECES - 1)), 1, $((PIECES - 2)), ...), whose rows near the horizon's rim cost"
    echo "the most (the table below), so that the cheap middle bands even out the workers' ends. A"
    echo "piece's *start* is its wall time less what it measured itself: reading its options and writing the piece,"
    echo "and for a worker's first piece the Java VM's start; *setup* is loading the patch and building the BRDF,"
    echo "*work* its pixels; the fixed cost column gives the sums' ratio and, in brackets, the largest piece's (a"
    echo "worker's first). By default the J"
    echo "workers share the machine's processors (--local 1: one worker with both cores; --local 2: two with one"
    echo "each), so a second worker adds only what one process's threads leave unused; with --cpus-per-task 1 each"
    echo "worker has one core whatever J, and the second worker's gain is $(printf "%.2f" "$(echo "scale=4; $local1c / $local2c" | bc)")x."
    echo
    echo "Where the rest goes. The flight recorder's samples of piece 3 on one processor ($samples samples; the most"
    echo "frequent methods on top of the stack: $top) put the exact spectrum's phase-centre expansions"
    echo "(\`ExactSpectrum.expand\` and \`.bounds\`, anywhere on the stack) in $expansions of them: the FFTs of the"
    echo "few centres a 100 x 100 patch needs take milliseconds, so keeping them on disk for the next piece would save"
    echo "nothing that a disk cache's read and checksum did not cost again. The pieces' work is the filtered"
    echo "reference's integrals over each pixel's footprint. What a process pays besides is Java's: its start, and"
    echo "the compiler, which compiles the code again in every process: $compiler s of compilation (-XX:+CITime) in"
    echo "that piece, run as a process of its own, against its $profiled_work s of work. The compiler runs on threads"
    echo "of its own, beside the work where a core is idle; where every core computes, it takes its time from the"
    echo "work, which runs interpreted or half-compiled until it is done. That is why a local worker computes all its"
    echo "pieces in one process: it pays both once. A Slurm task is a process of its own and pays them per piece"
    echo "(choose fewer, larger pieces there). What remains of the second worker's shortfall is the compilation"
    echo "that one worker of one processor does beside its work and two must share, what is left"
    echo "of the last pieces' imbalance and the machine's other load. Compiling less does not pay: with the"
    echo "first tier alone (-XX:TieredStopAtLevel=1) the same piece works $c1_work s."
    echo
    echo "| piece | rows | local 1: wall | start | setup | work | local 2: wall | start | setup | work |"
    echo "| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    join -t'|' <(pieces "$out/l1.log") <(pieces "$out/l2.log" | cut -d'|' -f1,3-) \
        | sort -t'|' -k1,1n | awk -F'|' '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7, $8, $9, $10 }'
    echo
    cat <<'EOF'
## On a Slurm cluster, and a bench sweep in pieces

How to run the pieces as a Slurm job array, and how a bench sweep splits and merges:
[guide/pieces.md](../guide/pieces.md).

EOF
    if [ -n "$bench_same" ]; then
        echo
        echo "In this run: the sweep \`${SWEEP[*]}\` whole and by \`submit --local 2\`: results.csv identical byte for"
        echo "byte but for the columns ms_per_frame and pareto: **$bench_same**."
    fi
    cat <<'EOF'

## The Slurm test

The test: `bash .ci/slurm-node` (as root, Debian) configures and starts a one-node Slurm on the machine (munge,
slurmctld and slurmd, this host as controller and node, no cgroups or accounting);
`mvn test -Dgroups=slurm -Ddiffract.excludedGroups=none` then runs `SlurmSubmitTest`, which submits a 4-task array
of a 64 x 64 reference map and compares the merged PNG and PFM with the single run's, byte for byte (`.ci/run`
does both). Without a Slurm that answers, that test fails, saying so.

For render farms whose managers run [Open Job Description](https://github.com/OpenJobDescription) jobs,
`docs/guide/openjd/brdfmap-pieces.yaml` is a job template of the same pieces: a Pieces step of N tasks (task P runs
`brdfmap ... --tile P-1/N --pieces DIR`) and a Merge step that depends on it. `openjd check` accepts it, and
`openjd run ... --step Merge --run-dependencies` runs it on one machine (its header shows the command).
EOF
    if [ -n "$openjd_same" ]; then
        echo "In this run: \`openjd check\` accepted it, and \`openjd run\` of its Merge step with its dependencies, the map"
        echo "above in $PIECES pieces, wrote a PNG identical byte for byte to the single run's: **$openjd_same**."
    fi
    echo
    if [ -n "${slurm:-}" ]; then
        echo "The script of the run above (\`/path/to/run/slurm/job.sbatch\`; its folder was temporary, here /path/to/run,"
        echo "and the repository's folder /path/to/diffract):"
        echo
        echo '```bash'
        sed -e "s#$out#/path/to/run#g" -e "s#$PWD#/path/to/diffract#g" "$out/slurm/job.sbatch"
        echo '```'
    fi
} > docs/measurements/pieces.md
cat docs/measurements/pieces.md
