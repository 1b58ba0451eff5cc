#!/usr/bin/env bash
# Runs every TinySEP benchmark against the real distribution (tinysep.jar as its own process) and writes
# benchmarks/RESULTS.md and the plots docs/images/bench-*.png:
#   ./benchmarks/run.sh            the full run (about 30-40 min on an idle 2-core machine)
#   ./benchmarks/run.sh --smoke    a few seconds each (what CI runs inside mvn verify), written to
#                                  benchmarks/target/smoke/ so RESULTS.md keeps the last full run
#   extra arguments go to the benchmarks, e.g. --only footprint,scale
# SKIP_BUILD=1 skips the Maven build (mvn -B -o -DskipTests package of the distribution and this module).
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ "${SKIP_BUILD:-0}" != "1" ]]; then
  mvn -B -o -q -DskipTests -pl benchmarks -am package
fi
args=(--dist runtime/org.tinysep.launcher/target/tinysep)
if [[ " $* " == *" --smoke "* ]]; then
  args+=(--out benchmarks/target/smoke/RESULTS.md --images benchmarks/target/smoke/images)
else
  args+=(--out benchmarks/RESULTS.md --images docs/images)
fi
exec java -cp "benchmarks/target/classes:$(cat benchmarks/target/classpath.txt)" org.tinysep.benchmarks.Main "${args[@]}" "$@"
