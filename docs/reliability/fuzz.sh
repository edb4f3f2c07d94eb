#!/bin/sh
# The fuzzing campaign of docs/reliability.md (Fuzzing): every parser fed INPUTS inputs (a million by
# default) from ParserFuzzTest's generators and mutations, one parser after another, at low priority
# (nice -n 10), in a build directory of its own so that other builds of this checkout do not disturb it.
#
#   docs/reliability/fuzz.sh                     # all parsers, 1 000 000 inputs each (hours: see the figures)
#   docs/reliability/fuzz.sh 100000 exr png      # some parsers, fewer inputs
#
# Each parser's report (inputs, accepted, rejected, seconds, the slowest input, findings) goes to
# $BUILD/fuzz-reports/NAME.txt, its Maven log to $BUILD/fuzz-logs/NAME.log, findings (shrunk inputs
# and what they did) to $BUILD/fuzz-findings/NAME/; a summary is printed at the end. A parser with
# findings exits its run with a test failure: the script says so and goes on with the next one.
set -u
cd "$(dirname "$0")/../.."
INPUTS=${1:-1000000}
[ $# -gt 0 ] && shift
PARSERS=${*:-obj mtl ply json gltf glb exr hdr pfm png vol tza}
BUILD=${STRAHL_FUZZ_BUILD:-$PWD/target/fuzz-campaign}
SEED=${STRAHL_FUZZ_SEED:-20260801}
mkdir -p "$BUILD/fuzz-logs"
echo "fuzz campaign: $INPUTS inputs each, seed $SEED, commit ${STRAHL_FUZZ_COMMIT:-$(git rev-parse --short HEAD 2>/dev/null || echo ?)}, $(date -u +%Y-%m-%dT%H:%MZ)"
for p in $PARSERS; do
    start=$(date +%s)
    if nice -n 10 mvn -B -Pfuzz test -Dstrahl.buildDirectory="$BUILD" -Dstrahl.fuzz.only="$p" -Dstrahl.fuzz.inputs="$INPUTS" \
            -Dstrahl.fuzz.seed="$SEED" > "$BUILD/fuzz-logs/$p.log" 2>&1; then
        verdict=ok
    else
        verdict="FAILED (findings or a build error: see $BUILD/fuzz-logs/$p.log)"
    fi
    echo "$p: $verdict, $(( $(date +%s) - start )) s wall clock, load $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)"
    cat "$BUILD/fuzz-reports/$p.txt" 2>/dev/null
done
