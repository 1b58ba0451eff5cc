#!/usr/bin/env bash
# Evaluates the inactivity alert on a recorded home through the real platform (evaluation/README.md):
#   ./evaluate.sh [A|B|<folder with events.csv, labels.csv>] [--collapses N] [--seed S] [--no-readme] ...
#   ./evaluate.sh falls [folder] [--loso] [--why]   fall detection on SisFall recordings (docs/fall-detection.md)
# SKIP_BUILD=1 uses the last build (the distribution in runtime/org.tinysep.launcher/target/tinysep).
set -euo pipefail
cd "$(dirname "$0")"
if [[ "${SKIP_BUILD:-0}" != "1" ]]; then
  mvn -B -o -q -pl evaluation -am package -DskipTests
fi
exec java -Dtinysep.repo="$PWD" -cp "evaluation/target/classes:evaluation/target/lib/*" \
  org.tinysep.evaluation.Evaluate "$@"
