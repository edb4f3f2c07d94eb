#!/bin/sh
# Regenerates every picture and figure of docs/experiments.md: builds strahl and its tests, then
# runs the experiments runner (src/test/java/dev/strahl/experiments/Experiments.java) on the
# class path with the test dependencies (JFreeChart draws the plots; it is a test dependency,
# never one of the library's). Writes the PNGs and docs/experiments/figures.txt.
#
#   docs/experiments/run.sh                    # everything, as on the page (about 25 minutes on 2 shared cores)
#   docs/experiments/run.sh --quick            # smaller sample counts: a try-out in a few minutes
#   docs/experiments/run.sh e5 e9              # only some experiments (figures-e5-e9.txt)
#   STRAHL_DATA=/path/to/data docs/experiments/run.sh   # with the Stanford bunny (meshes/bunny/bun_zipper.ply)
#
# Run from anywhere; Maven and a JDK 17+ are needed, as for the build.
set -eu
cd "$(dirname "$0")/../.."
start=$(date +%s)
mvn -B -q -DskipTests package
mvn -B -q dependency:build-classpath -Dmdep.includeScope=test -Dmdep.outputFile=target/experiments.classpath
set -- "$@"
if [ -n "${STRAHL_DATA:-}" ]; then set -- "$@" --data "$STRAHL_DATA"; fi
java -Xmx2g -Djava.awt.headless=true -cp "target/classes:target/test-classes:$(cat target/experiments.classpath)" \
    dev.strahl.experiments.Experiments docs/experiments . "$@"
echo "docs/experiments/run.sh: $(( $(date +%s) - start )) s in all"
