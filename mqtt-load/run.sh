#!/bin/sh
# The central board's load test (docs/central-board.md): one real Mosquitto, the board, N simulated flats.
# Usage: mqtt-load/run.sh [flats=200] [seconds=180]   (from the repository root; needs mosquitto: scripts/install-deps.sh)
# Rates per flat: heartbeat every 10 s, a device state every 2 s, occupancy every 30 s, an alert every 30 s
# (acknowledged by the board, answered ACKNOWLEDGED + CLEARED + emptied by the flat). The report is printed and
# kept in mqtt-load/results/<UTC time>.txt.
set -e
cd "$(dirname "$0")/.."
FLATS=${1:-200}
SECONDS_RUN=${2:-180}
mvn -B -o -q -pl bundles/fleet/org.tinysep.mqtt.board -am verify \
  -Dtest=LoadSmokeTest -Dsurefire.failIfNoSpecifiedTests=false \
  -Dload.flats="$FLATS" -Dload.seconds="$SECONDS_RUN" -Dload.heartbeatSeconds=10 -Dload.stateMillis=2000 \
  -Dload.alertSeconds=30 -Dload.occupancySeconds=30
mkdir -p mqtt-load/results
OUT=mqtt-load/results/$(date -u +%Y%m%dT%H%M%SZ).txt
cp bundles/fleet/org.tinysep.mqtt.board/target/mqtt-load-report.txt "$OUT"
cat "$OUT"
echo "kept in $OUT"
