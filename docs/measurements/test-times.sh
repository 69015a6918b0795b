#!/usr/bin/env bash
# Runs README's test command and then the long tests (as .ci/run does), and writes docs/measurements/test-times.md: the wall
# time of each run and every test class's time, slowest first, from surefire's reports.
set -euo pipefail
cd "$(dirname "$0")/../.."
times() {  # class and seconds of every report in target/surefire-reports, slowest first
    for f in target/surefire-reports/TEST-*.xml; do
        t=$(grep -o '<testsuite [^>]*' "$f" | grep -o ' time="[0-9.]*"' | head -1 | tr -dc '0-9.')
        n=$(grep -o '<testsuite [^>]*' "$f" | grep -o ' tests="[0-9]*"' | head -1 | tr -dc '0-9')
        echo "$t $n $(basename "$f" .xml | sed 's/^TEST-diffract\.//')"
    done | sort -rn
}
table() {
    echo "| class | tests | seconds |"
    echo "| --- | ---: | ---: |"
    awk '{ printf "| `%s` | %d | %.1f |\n", $3, $2, $1 }'
}
rm -rf target/surefire-reports
start=$(date +%s); mvn -B -ntp -q test > /dev/null; main_s=$(( $(date +%s) - start ))
main=$(times)
rm -rf target/surefire-reports
start=$(date +%s); mvn -B -ntp -q test -Dgroups=long -Ddiffract.excludedGroups=none > /dev/null
long_s=$(( $(date +%s) - start ))
long=$(times)
cores=$(nproc)
{
    echo "# Test times"
    echo
    echo "Made by \`bash docs/measurements/test-times.sh\` on $cores cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs))."
    echo "A busy machine takes 2-5 times longer; no test depends on how long anything takes."
    echo
    echo "README's test command, \`mvn -B -ntp test\`: $main_s s in all (compiling included), $(echo "$main" | awk '{n += $2} END {print n}') tests."
    echo
    echo "$main" | table
    echo
    echo "The long tests (tag \`long\`: sweeps and reports), which \`.ci/run\` runs after it with"
    echo "\`mvn -B -ntp test -Dgroups=long -Ddiffract.excludedGroups=none\`: $long_s s in all."
    echo
    echo "$long" | table
} > docs/measurements/test-times.md
cat docs/measurements/test-times.md | head -8
