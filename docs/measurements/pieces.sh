#!/usr/bin/env bash
# Times a reference BRDF map computed whole, by `submit --local 1 --piece-count 1` (the whole map as one worker), and by
# `submit --local J` (J = 1 and 2, 8 pieces each), checks that all write the same bytes, and splits each piece's time
# into its fixed cost (Java start, loading the patch and building the BRDF) and its work (the pixels). Where a Slurm
# answers (sinfo; bash .ci/slurm-node starts a one-node one here), also times the pieces as a job array
# (`submit --slurm`) and shows the job script it writes. Profiles one piece with Java's flight recorder (where its work
# goes), and splits a small bench sweep into pieces (merged rows against the single run's).
# Writes docs/pieces.md. SIZE=64 bash docs/pieces.sh for a quicker run.
set -euo pipefail
cd "$(dirname "$0")/.."
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
    if openjd check docs/openjd/brdfmap-pieces.yaml > "$out/openjd.log" 2>&1 \
        && openjd run docs/openjd/brdfmap-pieces.yaml --step Merge --run-dependencies -p Diffract="$PWD/diffract" \
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
    echo "Generated by \`bash docs/pieces.sh\` (SIZE=$SIZE, $PIECES pieces) on $(nproc) cores, load average $load_before"
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
## On a Slurm cluster

The same pieces run as the tasks of one Slurm job array: `--slurm` in place of `--local J`, on a cluster's login
node, with the pieces' folder on a disk every node reads and writes.

```bash
./diffract submit --slurm --piece-count 64 --max-running 16 --cpus-per-task 4 --keep-pieces /shared/me/ref-pieces \
    --cache-dir /shared/me/diffract-cache --partition short --time-limit 1:00:00 \
    -- brdfmap --patch scan.gwy --theta-i 30 --size 512 --exposure auto -o ref.png --pfm ref.pfm
```

- **What runs.** submit checks the brdfmap command as a single run would (outputs included), writes
  `DIR/job.sbatch` (`--keep-pieces DIR`, required with `--slurm`, as is `--piece-count N`) and submits it with
  `sbatch --parsable --wait`. Task I of the array (`#SBATCH --array=0-(N-1)`) runs `brdfmap ... --tile I/N --pieces
  DIR` with the Java, class path (the jar) and heap of the submitting `./diffract`, in the folder submit ran in, so
  the options' relative paths mean the same; these must be on a disk the nodes share, as a cluster's software and
  home folders usually are. Its log is `DIR/piece-I-of-N.log`. The script stays: `sbatch DIR/job.sbatch` runs the job
  again as it was, `sbatch --array=3,5 DIR/job.sbatch` only pieces 3 and 5.
- **Throttling.** `--max-running T` writes `--array=0-(N-1)%T`: at most T tasks run at once, the rest wait in the
  queue (a fair share of a busy cluster, or of a licence or disk). Without it the scheduler starts as many as it has
  room for.
- **Processors.** `--cpus-per-task C` (default 1) asks for C processors per task and starts Java with
  `-XX:ActiveProcessorCount=$SLURM_CPUS_PER_TASK`, so a task's threads match what it was given even where Slurm
  confines no processes (no cgroups) and Java would see the whole node. Each task is a Java process of its own and
  pays Java's start and compilation (above) whatever C: fewer, larger pieces waste less of them.
- **GPU nodes.** `--gpus-per-task G` adds `--gres=gpu:G` and, in the script, `unset DISPLAY` and `DIFFRACT_GL=egl`:
  OpenGL in a task runs on headless EGL on the node's first device ([headless-gl.md](headless-gl.md)), never on a
  forwarded X display. brdfmap's pieces compute on the CPU; a turntable's frames (`-- render SCENE --turntable F
  ... -o OUT.gif`, split into runs of frames the same way) draw with the node's GPU.
- **Cache.** `--cache-dir DIR` exports `DIFFRACT_CACHE=DIR` in the script: the tasks share one disk cache, and what
  one precomputed (a patch's Taylor terms, for the variants that use them; the reference uses none) the others read
  instead of computing it again. Without it each node uses its own default cache folder.
- **Scheduler settings.** `--partition NAME` and `--time-limit TIME` (sbatch's `--time`) become `#SBATCH` lines;
  `--sbatch-option=--account=lab` (repeatable) passes any other sbatch option into the script as it is.
- **The merge.** `sbatch --wait` returns when every task of the array has ended; submit then merges in its own
  process, into the files the brdfmap command names, bit for bit those of the single run. With `--no-wait` it
  returns once the job is queued and prints the merge command (absolute paths) to run after it; a dependent job does
  it on the cluster: `sbatch --dependency=afterok:JOBID --wrap "./diffract merge DIR -o ref.png --pfm ref.pfm"`.
- **Failures, one line each, exit code 2:** no `sbatch` on the machine; a job the scheduler refuses (sbatch's own
  reason, e.g. an unknown partition); tasks that died, with the pieces they did not write, the first one's log and
  the `sbatch --array=...` that computes them again; pieces that are still missing at the merge (merge names them).
- **Running again** computes every piece again, as `--local` does: each piece's files are replaced atomically, and a
  piece computed again has the same bytes. To compute only the missing pieces, resubmit the script for them
  (above), then merge.

## A bench sweep in pieces

The bench's sweep splits the same way, into runs of its configurations:

```bash
./diffract bench --quick --tile 0/4 --pieces /shared/me/bench-pieces    # task 0 of 4; 1, 2, 3 alike
./diffract merge /shared/me/bench-pieces -o out/bench
./diffract submit --local 2 -- bench --quick -o out/bench               # or --slurm --piece-count N --keep-pieces DIR
```

A piece measures its configurations (the reference maps and terms they need come from the shared disk cache, or
are computed) and writes their rows into its manifest, every number as the exact double it measured. Merge writes
`results.csv`, `results.md`, `pareto.md`, `targets.md`, `machine.txt` and `pareto.png` from those rows as one run
writes them: the same configurations in the same order, the same errors, the Pareto front over all rows, the
GPU times each piece measured. What it cannot reproduce: the times themselves, which every run measures again (two
single runs differ in them too), and, in `targets.md`, the direct comparison of NMM with FLSS at 1 nm, which needs
both configurations' maps in one process ("-" there). Pieces measured on different OpenGL renderers are refused:
their times do not compare. On a software rasteriser (llvmpipe) two local workers share the processors that draw,
so their times are not those of one run; measure times with one worker per machine or GPU. `--gpu-suite` and
`--filtering` run whole.
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
`docs/openjd/brdfmap-pieces.yaml` is a job template of the same pieces: a Pieces step of N tasks (task P runs
`brdfmap ... --tile P-1/N --pieces DIR`) and a Merge step that depends on it. `openjd check` accepts it, and
`openjd run ... --step Merge --run-dependencies` runs it on one machine (its header shows the command).
EOF
    if [ -n "$openjd_same" ]; then
        echo "In this run: \`openjd check\` accepted it, and \`openjd run\` of its Merge step with its dependencies, the map"
        echo "above in $PIECES pieces, wrote a PNG identical byte for byte to the single run's: **$openjd_same**."
    fi
    echo
    if [ -n "${slurm:-}" ]; then
        echo "The script of the run above (\`$out/slurm/job.sbatch\`; its folder was temporary):"
        echo
        echo '```bash'
        cat "$out/slurm/job.sbatch"
        echo '```'
    fi
} > docs/pieces.md
cat docs/pieces.md
