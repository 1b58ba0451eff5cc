#!/usr/bin/env bash
# The demo flat of ./run.sh: when no hardware is configured, the platform runs with the simulated flat A
# (simulator/, 20 AmICA + 3 Sun SPOT nodes, a person and a dog, demo-day scenario) in lock-step virtual time.
# The demo runs in its own throwaway state: it never writes the distribution's etc/ nor the user's state folder.
#   scripts/demo-flat.sh wanted <dist>          exit 0 if the demo should run (TINYSEP_DEMO != 0, no hardware configured)
#   scripts/demo-flat.sh prepare <dist> <demo>  (re)creates the demo folder <demo>, wiping the previous demo's:
#       <demo>/home  the demo's distribution: bundles/ (a link to <dist>/bundles), deploy/ (empty), etc/ = a copy of
#                    <dist>/etc without the Mail Manager's settings (the demo never mails a real caregiver), plus
#                    flat A's room placements and the clock in EXTERNAL mode (the simulator drives it)
#       <demo>/var   the demo's state folder: flat A's house plan, the synchroniser key sync.key (0600)
#     start the platform with:  java -jar <dist>/tinysep.jar --home <demo>/home --var <demo>/var
#     (a demo home, not a launcher option for another etc/: whatever finds etc/ through tinysep.home - FileInstall,
#     tinysep:backup/restore, drivers-list paths - sees the demo's)
#   scripts/demo-flat.sh simulate <dist> <demo> runs the simulated day against that platform (waits for it first),
#       (up to TINYSEP_DEMO_WAIT=60 s), then BYE returns the platform clock to real time (TINYSEP_DEMO_FROM /
#       TINYSEP_DEMO_UNTIL: the span, HH:MM)
#   scripts/demo-flat.sh forget-old-demo <dist> removes the etc/ files an older demo (before the demo had its own
#       state) wrote into <dist>/etc: they froze the clock in EXTERNAL mode after the demo
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
flat="$repo/simulator/src/main/resources/flats/flat-a"
usage="usage: demo-flat.sh wanted|forget-old-demo <dist> | prepare|simulate <dist> <demo folder>"
cmd="${1:?$usage}"
dist="${2:?$usage}"
etc="$dist/etc"
marker=".tinysep-demo" # a demo folder holds it; prepare wipes only such folders
old_demo_line="# demo flat A (scripts/demo-flat.sh)"

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

cfg_value() { # cfg_value <file> <key> <default>: the key's value in a ConfigAdmin .cfg file
  local v
  v=$(sed -n "s/^[[:space:]]*$2[[:space:]]*[=:][[:space:]]*\([0-9][0-9]*\)[[:space:]]*$/\1/p" "$1" 2>/dev/null | tail -1)
  echo "${v:-$3}"
}

demo_folder() {
  demo="${3:?$usage}"
  case "$demo" in /*) ;; *) demo="$PWD/$demo" ;; esac
}

case "$cmd" in
  wanted)
    [ "${TINYSEP_DEMO:-1}" != "0" ] && ! hardware_configured ;;
  forget-old-demo)
    for f in "$etc/org.tinysep.timecontroller.cfg" "$etc/org.tinysep.houseinformation.placement.cfg"; do
      if [ -f "$f" ] && head -1 "$f" | grep -qF "$old_demo_line"; then
        rm -f "$f"
        echo "Removed $f: an older demo wrote it (it kept the clock frozen in EXTERNAL mode after the demo)."
      fi
    done ;;
  prepare)
    demo_folder "$@"
    if [ -e "$demo" ] && [ ! -f "$demo/$marker" ]; then
      echo "demo flat: $demo exists and is not a demo folder (no $marker): not wiping it" >&2
      exit 1
    fi
    rm -rf "$demo"
    mkdir -p "$demo/home/etc" "$demo/home/deploy" "$demo/var"
    chmod 700 "$demo/var"
    echo "state of the TinySEP demo flat, thrown away at the next demo start (scripts/demo-flat.sh)" > "$demo/$marker"
    ln -s "$(cd "$dist" && pwd)/bundles" "$demo/home/bundles"
    for f in "$etc"/*; do
      [ -f "$f" ] || continue
      case "$(basename "$f")" in
        org.tinysep.mailmanager.cfg) ;; # the demo never mails a real caregiver: alerts are written to the console
        org.tinysep.timecontroller.cfg | org.tinysep.houseinformation.placement.cfg) ;; # the demo's own, below
        *) cp -p "$f" "$demo/home/etc/" ;;
      esac
    done
    {
      echo "# demo flat A: node address = room (demo state, scripts/demo-flat.sh)"
      echo "placements=$(placements)"
    } > "$demo/home/etc/org.tinysep.houseinformation.placement.cfg"
    {
      echo "# demo flat A: the simulator drives the clock; it returns to real time when the simulated day ends"
      echo "# (demo state, scripts/demo-flat.sh)"
      if [ -f "$etc/org.tinysep.timecontroller.cfg" ]; then # keep the user's port, address and key settings
        grep -Ev '^[[:space:]]*mode[[:space:]]*[=:]' "$etc/org.tinysep.timecontroller.cfg" || true
      fi
      echo "mode=EXTERNAL"
      echo "syncKeyFile=$demo/var/sync.key"
    } > "$demo/home/etc/org.tinysep.timecontroller.cfg"
    cp "$flat/house.xml" "$demo/var/house.xml"
    (umask 077 && od -An -N32 -tx1 /dev/urandom | tr -d ' \n' > "$demo/var/sync.key" && echo >> "$demo/var/sync.key") ;;
  simulate)
    demo_folder "$@"
    jar=$(ls "$repo"/simulator/target/org.tinysep.simulator-*.jar 2>/dev/null | grep -v -- '-sources\|-tests' | head -1)
    [ -n "$jar" ] || { echo "demo flat: simulator jar missing (build first)" >&2; exit 1; }
    demo_etc="$demo/home/etc"
    sleep "${TINYSEP_DEMO_DELAY:-8}" # let the platform start and read its etc/
    exec java -jar "$jar" --lockstep --wait-platform "${TINYSEP_DEMO_WAIT:-60}" \
      --from "${TINYSEP_DEMO_FROM:-06:30}" --until "${TINYSEP_DEMO_UNTIL:-23:00}" \
      --progress 120 --release-clock --sync-key "$demo/var/sync.key" \
      --amica-port "$(cfg_value "$demo_etc/org.tinysep.amica.busradio.udp.cfg" port 47011)" \
      --sunspot-port "$(cfg_value "$demo_etc/org.tinysep.sunspot.busradio.cfg" udpPort 47012)" \
      --sync-port "$(cfg_value "$demo_etc/org.tinysep.timecontroller.cfg" syncPort 47020)" ;;
  *) echo "$usage" >&2; exit 2 ;;
esac
