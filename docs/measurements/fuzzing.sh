#!/usr/bin/env bash
# The long fuzzing run of docs/measurements/fuzzing.md: each target of ParsersFuzzTest fuzzed in turn by Jazzer (JAZZER_FUZZ=1)
# until its maxExecutions (500 000 inputs for the height-field readers, 100 000 for each other parser), in a JVM of
# its own (the surefire execution fuzz-corpus). Prints one line per target: the inputs run, the seconds, and whether
# it ended without a finding. Findings are written beside the corpus by Jazzer (docs/measurements/fuzzing.md says where to move
# them). Logs: target/fuzz-TARGET.log.
set -uo pipefail
cd "$(dirname "$0")/../.."
mvn -B -ntp -q test-compile > /dev/null
status=0
for target in heightFields sceneFiles objMeshes termFolders cacheEntries pieceManifests; do
    log="target/fuzz-$target.log"
    # RegexRoadblocks steers inputs through the JDK's regular expressions by hooking their matching: it makes the
    # header and text parsers six times slower here, and none of them takes a pattern from its input
    JAZZER_FUZZ=1 JAZZER_DISABLED_HOOKS=com.code_intelligence.jazzer.sanitizers.RegexRoadblocks \
        mvn -B -ntp surefire:test@fuzz-corpus -Ddiffract.fuzzTest="ParsersFuzzTest#$target" > "$log" 2>&1
    code=$?
    done_line=$(grep -a -o 'Done [0-9]* runs in [0-9]* second(s)' "$log" | tail -1)
    echo "$target: ${done_line:-no summary} (exit $code)"
    [ "$code" -eq 0 ] || status=1
done
exit $status
