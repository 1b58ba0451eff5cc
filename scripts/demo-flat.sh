#!/usr/bin/env bash
# The demo flat of ./run.sh: when no hardware is configured, the platform runs with the simulated flat A
# (simulator/, 20 AmICA + 3 Sun SPOT nodes, a person and a dog, demo-day scenario) in lock-step virtual time.
#   scripts/demo-flat.sh wanted <dist>    exit 0 if the demo should run (TINYSEP_DEMO != 0, no hardware configured)
#   scripts/demo-flat.sh prepare <dist> [var]   house plan (into the state folder var, default <dist>/var), room
#                                         placements, EXTERNAL clock (only files the user has not made)
#   scripts/demo-flat.sh simulate <dist>  runs the simulated day against the platform (waits for it first)
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
flat="$repo/simulator/src/main/resources/flats/flat-a"
cmd="${1:?usage: demo-flat.sh wanted|prepare|simulate <dist>}"
dist="${2:?distribution folder}"
etc="$dist/etc"

hardware_configured() {
  compgen -G "$etc/org.tinysep.amica.busradio.serial-*.cfg" >/dev/null && return 0
  grep -Eq '^[[:space:]]*(serialPort[[:space:]]*=[[:space:]]*[^[:space:]]|sdkEnabled[[:space:]]*=[[:space:]]*true)' \
    "$etc/org.tinysep.sunspot.busradio.cfg" 2>/dev/null && return 0
  return 1
}

placements() { # node address=room for every node of flat A except pet collars (they move with the pet)
  grep -v '^[[:space:]]*#' "$flat/nodes.txt" | awk -F'|' 'NF >= 5 && $6 !~ /agent=/ {
    gsub(/^[ \t]+|[ \t]+$/, "", $3); gsub(/^[ \t]+|[ \t]+$/, "", $5);
    printf "%s%s=%s", (n++ ? ", " : ""), $3, $5 }'
}

case "$cmd" in
  wanted)
    [ "${TINYSEP_DEMO:-1}" != "0" ] && ! hardware_configured ;;
  prepare)
    var="${3:-$dist/var}"
    mkdir -p "$var"
    [ -f "$var/house.xml" ] || cp "$flat/house.xml" "$var/house.xml"
    [ -f "$etc/org.tinysep.houseinformation.placement.cfg" ] || {
      echo "# demo flat A (scripts/demo-flat.sh): node address = room"
      echo "placements=$(placements)"
    } > "$etc/org.tinysep.houseinformation.placement.cfg"
    [ -f "$etc/org.tinysep.timecontroller.cfg" ] || {
      echo "# demo flat A (scripts/demo-flat.sh): the simulator drives the clock; 'tinysep:time real' to leave it"
      echo "mode=EXTERNAL"
    } > "$etc/org.tinysep.timecontroller.cfg" ;;
  simulate)
    jar=$(ls "$repo"/simulator/target/org.tinysep.simulator-*.jar 2>/dev/null | grep -v -- '-sources' | head -1)
    [ -n "$jar" ] || { echo "demo flat: simulator jar missing (build first)" >&2; exit 1; }
    sleep "${TINYSEP_DEMO_DELAY:-8}" # let the platform start and read etc/
    exec java -jar "$jar" --lockstep --from 06:30 --until 23:00 --progress 120 ;;
  *) echo "usage: demo-flat.sh wanted|prepare|simulate <dist>" >&2; exit 2 ;;
esac
