#!/usr/bin/env bash
# Evaluates the inactivity alert on a recorded home through the real platform (evaluation/README.md):
#   ./evaluate.sh [A|B|<folder with events.csv, labels.csv>] [--collapses N] [--seed S] [--no-readme] ...
#   ./evaluate.sh falls [folder] [--loso] [--why]   fall detection on SisFall recordings (docs/fall-detection.md)
#   ./evaluate.sh --engine core [--model uniform|moving|both] [--split half|cvK] [--collapses N] A B A:nomotion B:two
#     the detector core without the platform (CoreSweep, seconds per home): one table for all homes
# SKIP_BUILD=1 uses the last build (the distribution in runtime/org.tinysep.launcher/target/tinysep).
set -euo pipefail
cd "$(dirname "$0")"
if [[ "${SKIP_BUILD:-0}" != "1" ]]; then
  mvn -B -o -q -pl evaluation -am package -DskipTests
fi
main=org.tinysep.evaluation.Evaluate
for a in "$@"; do
  [[ "$a" == "core" && "${prev:-}" == "--engine" ]] && main=org.tinysep.evaluation.CoreSweep
  prev="$a"
done
exec java -Dtinysep.repo="$PWD" -cp "evaluation/target/classes:evaluation/target/lib/*" "$main" "$@"
