#!/usr/bin/env bash
# The demo flat of ./run.sh: when no hardware is configured, the platform runs with the simulated flat A
# (simulator/, 20 AmICA + 3 Sun SPOT nodes, Anna's pendant, a person and a dog, demo-day scenario) in lock-step
# virtual time.
# The demo runs in its own throwaway state: it never writes the distribution's etc/ nor the user's state folder.
#   scripts/demo-flat.sh wanted <dist>          exit 0 if the demo should run (TINYSEP_DEMO != 0, no hardware configured)
#   scripts/demo-flat.sh prepare <dist> <demo>  (re)creates the demo folder <demo>, wiping the previous demo's:
#       <demo>/home  the demo's distribution: bundles/ (a link to <dist>/bundles), deploy/ (empty), etc/ = a copy of
#                    <dist>/etc without the Mail Manager's settings (the demo never mails a real caregiver), plus
#                    flat A's room placements, who wears its person nodes (Anna) and the clock in EXTERNAL mode (the
#                    simulator drives it)
#       <demo>/var   the demo's state folder: flat A's house plan, the synchroniser key sync.key (0600)
#     start the platform with:  java -jar <dist>/tinysep.jar --home <demo>/home --var <demo>/var
#     (a demo home, not a launcher option for another etc/: whatever finds etc/ through tinysep.home - FileInstall,
#     tinysep:backup/restore, drivers-list paths - sees the demo's)
#     prepare keeps the demo's web passwords (<demo>/var/web/) across demo starts, and gives the demo free ports:
#     the configured ones (AmICA 47011, Sun SPOT 47012, clock 47020 UDP; web 8080 TCP) when free, else free ones
#     (written into <demo>/home/etc; <demo>/ports says which)
#   scripts/demo-flat.sh ports-ours <demo> <pid> exit 0 when every UDP port the simulator will send to is bound by the
#       process <pid> (the platform this run started); exit 3 with a plain message when another program holds one,
#       or when <pid> has not bound them within TINYSEP_DEMO_WAIT (default 60) s
#   scripts/demo-flat.sh simulate <dist> <demo> [<pid>] runs the simulated day against that platform (waits for it
#       first, up to TINYSEP_DEMO_WAIT=60 s; with <pid>, refuses - exit 3 - unless the ports are that process's).
#       Anna wears a pendant (a Sun SPOT person node, flat A's anna-pendant): her collapse is a fall it reports, a
#       FALL alert within seconds. TINYSEP_DEMO_PENDANT=0: a day without the pendant (simulator --no-pendant): the
#       room sensors only, and the inactivity alert after the bathroom's limit is what notices her collapse.
#       TINYSEP_DEMO_FROM / TINYSEP_DEMO_UNTIL: the span, HH:MM (default 06:30-23:00). The platform's clock stays
#       on the demo day afterwards (syncTimeout=0, no BYE) until the user says `tinysep:time real`;
#       TINYSEP_DEMO_RELEASE=1 returns it to real time at the end instead
#   scripts/demo-flat.sh forget-old-demo <dist> removes the etc/ files an older demo (before the demo had its own
#       state) wrote into <dist>/etc: they froze the clock in EXTERNAL mode after the demo
set -Eeuo pipefail
# an unexpected failure says where, instead of ending the demo without a word (the log is shown by ./run.sh)
trap 'echo "demo flat: stopped by a failing command at line $LINENO (exit $?)" >&2' ERR
repo="$(cd "$(dirname "$0")/.." && pwd)"
flat="$repo/simulator/src/main/resources/flats/flat-a"
usage="usage: demo-flat.sh wanted|forget-old-demo <dist> | prepare <dist> <demo folder> | simulate <dist> <demo folder> [<platform pid>] | ports-ours <demo folder> <platform pid>"
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

persons() { # node address=wearer for every person node of flat A (option person=<name>)
  grep -v '^[[:space:]]*#' "$flat/nodes.txt" | awk -F'|' 'NF >= 6 && match($6, /person=[^ \t]+/) {
    gsub(/^[ \t]+|[ \t]+$/, "", $3);
    printf "%s%s=%s", (n++ ? ", " : ""), $3, substr($6, RSTART + 7, RLENGTH - 7) }'
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

set_key() { # set_key <cfg file> <key> <value>: the key's line replaced (or added)
  local f="$1" tmp
  tmp=$(mktemp "$f.XXXXXX")
  { [ -f "$f" ] && grep -Ev "^[[:space:]]*$2[[:space:]]*[=:]" "$f"; echo "$2=$3"; } > "$tmp" || true
  mv -f "$tmp" "$f"
}

port_busy() { # port_busy udp|tcp <port>: exit 0 when some socket on this machine is bound to it
  local flag=-lun
  [ "$1" = tcp ] && flag=-ltn
  [ -n "$(ss -H $flag "sport = :$2" 2>/dev/null)" ]
}

free_port() { # free_port udp|tcp <preferred>: the preferred port when free, else a free one (from 20000 up)
  local p="$2" tries=0
  while port_busy "$1" "$p" || { [ "$1" = udp ] && port_busy tcp "$p"; }; do
    p=$((20000 + RANDOM % 30000)); tries=$((tries + 1))
    [ $tries -lt 200 ] || { echo "demo flat: no free $1 port found" >&2; return 1; }
  done
  echo "$p"
}

demo_ports() { # lines "udp <port> <what>" the simulator sends to
  local e="$demo/home/etc"
  echo "udp $(cfg_value "$e/org.tinysep.amica.busradio.udp.cfg" port 47011) AmICA bus radio"
  echo "udp $(cfg_value "$e/org.tinysep.sunspot.busradio.cfg" udpPort 47012) Sun SPOT bus radio"
  echo "udp $(cfg_value "$e/org.tinysep.timecontroller.cfg" syncPort 47020) platform clock (time sync)"
}

holder() { # holder udp|tcp <port>: "pid=N (name)" of the process bound to the port, or "" when none (or not visible)
  local flag=-lunp
  [ "$1" = tcp ] && flag=-ltnp
  # never fails: ss can exit 1 when a process it inspects ends meanwhile, and under set -e that would end the demo
  # silently; sed reads all its input so that no SIGPIPE fails the pipe
  { ss -H $flag "sport = :$2" 2>/dev/null || true; } | sed -n 's/.*users:(("\([^"]*\)",pid=\([0-9]*\).*/pid=\2 (\1)/p' \
    | sed -n 1p
}

ports_ours() { # ports_ours <pid> <wait seconds>: 0 when every demo port is bound by <pid>; 3 with a message if not
  local pid="$1" deadline=$((SECONDS + $2)) proto port what h
  while :; do
    local missing="" foreign="" unseen=""
    while read -r proto port what; do
      # bound first, then by whom: asked the other way round, a port the platform binds between the two questions
      # looked held by a program nobody can see, and the demo day was refused (a CI run of DemoDayIT)
      if ! port_busy "$proto" "$port"; then
        missing+="  $proto port $port ($what) is not bound yet"$'\n'
        continue
      fi
      h=$(holder "$proto" "$port")
      if [ -z "$h" ]; then # asked again next second: ss may miss a process that binds or starts meanwhile
        unseen+="  $proto port $port ($what) is held by a program this user cannot see"$'\n'
      elif [ "${h#pid=$pid }" = "$h" ]; then
        foreign+="  $proto port $port ($what) is held by another program, $h, not by the platform started here (pid $pid)"$'\n'
      fi
    done < <(demo_ports)
    if [ -n "$unseen" ] && [ $SECONDS -ge $deadline ]; then
      foreign+="$unseen"
    fi
    if [ -n "$foreign" ]; then
      printf 'demo flat: not sending the demo day: it would go to another program.\n%s' "$foreign" >&2
      echo "  Stop that program, or start the demo again (./run.sh picks free ports when the configured ones are taken)." >&2
      return 3
    fi
    [ -z "$missing" ] && [ -z "$unseen" ] && return 0
    if ! kill -0 "$pid" 2>/dev/null; then
      echo "demo flat: the platform (pid $pid) has stopped: not sending the demo day" >&2
      return 3
    fi
    if [ $SECONDS -ge $deadline ]; then
      printf 'demo flat: not sending the demo day: the platform (pid %s) did not bind its ports within %s s.\n%s' \
        "$pid" "$2" "$missing" >&2
      return 3
    fi
    sleep 1
  done
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
    kept=""
    if [ -d "$demo/var/web" ]; then # the web passwords (hashes) survive demo starts
      kept=$(mktemp -d "${TMPDIR:-/tmp}/tinysep-demo-web.XXXXXX")
      cp -pr "$demo/var/web" "$kept/"
    fi
    rm -rf "$demo"
    mkdir -p "$demo/home/etc" "$demo/home/deploy" "$demo/var"
    chmod 700 "$demo/var"
    if [ -n "$kept" ]; then
      cp -pr "$kept/web" "$demo/var/" && rm -rf "$kept"
    fi
    echo "state of the TinySEP demo flat, thrown away at the next demo start (scripts/demo-flat.sh)" > "$demo/$marker"
    ln -s "$(cd "$dist" && pwd)/bundles" "$demo/home/bundles"
    for f in "$etc"/*; do
      [ -f "$f" ] || continue
      case "$(basename "$f")" in
        org.tinysep.mailmanager.cfg) ;; # the demo never mails a real caregiver: alerts are written to the console
        org.tinysep.timecontroller.cfg | org.tinysep.houseinformation.placement.cfg) ;; # the demo's own, below
        org.tinysep.sunspot.person.cfg) ;; # the demo's own, below
        *) cp -p "$f" "$demo/home/etc/" ;;
      esac
    done
    {
      echo "# demo flat A: node address = room (demo state, scripts/demo-flat.sh)"
      echo "placements=$(placements)"
    } > "$demo/home/etc/org.tinysep.houseinformation.placement.cfg"
    {
      echo "# demo flat A: who wears which person node (demo state, scripts/demo-flat.sh)"
      echo "persons=$(persons)"
    } > "$demo/home/etc/org.tinysep.sunspot.person.cfg"
    {
      echo "# demo flat A: the simulator drives the clock; it stays on the demo day until tinysep:time real"
      echo "# (demo state, scripts/demo-flat.sh)"
      if [ -f "$etc/org.tinysep.timecontroller.cfg" ]; then # keep the user's port, address and key settings
        grep -Ev '^[[:space:]]*mode[[:space:]]*[=:]' "$etc/org.tinysep.timecontroller.cfg" || true
      fi
      echo "mode=EXTERNAL"
      echo "syncKeyFile=$demo/var/sync.key"
    } > "$demo/home/etc/org.tinysep.timecontroller.cfg"
    # the clock stays on the demo day after it is played (no return to real time after 120 s without a TICK)
    set_key "$demo/home/etc/org.tinysep.timecontroller.cfg" syncTimeout 0
    # free ports: the configured ones when nobody holds them, else others (the demo never sends to a stranger)
    e="$demo/home/etc"
    : > "$demo/ports"
    for spec in "udp org.tinysep.amica.busradio.udp.cfg port 47011" "udp org.tinysep.sunspot.busradio.cfg udpPort 47012" \
        "udp org.tinysep.timecontroller.cfg syncPort 47020" "tcp org.apache.felix.http.cfg org.osgi.service.http.port 8080"; do
      read -r proto file key def <<< "$spec"
      want=$(cfg_value "$e/$file" "$key" "$def")
      got=$(free_port "$proto" "$want")
      set_key "$e/$file" "$key" "$got"
      echo "$proto $key=$got ($file)" >> "$demo/ports"
      [ "$got" = "$want" ] || echo "DEMO: $proto port $want ($key, $file) is taken by another program; the demo uses $got"
    done
    cp "$flat/house.xml" "$demo/var/house.xml"
    (umask 077 && od -An -N32 -tx1 /dev/urandom | tr -d ' \n' > "$demo/var/sync.key" && echo >> "$demo/var/sync.key") ;;
  simulate)
    demo_folder "$@"
    jar=$(ls "$repo"/simulator/target/org.tinysep.simulator-*.jar 2>/dev/null | grep -v -- '-sources\|-tests' | head -1)
    [ -n "$jar" ] || { echo "demo flat: simulator jar missing (build first)" >&2; exit 1; }
    demo_etc="$demo/home/etc"
    if [ -n "${4:-}" ]; then # the platform's pid: send only to ports it holds itself
      ports_ours "$4" "${TINYSEP_DEMO_WAIT:-60}" || exit 3
      sleep 2 # its drivers have bound: a moment for the rest of the start
    else
      sleep "${TINYSEP_DEMO_DELAY:-8}" # let the platform start and read its etc/
    fi
    release=()
    [ "${TINYSEP_DEMO_RELEASE:-0}" = "1" ] && release=(--release-clock)
    if [ "${TINYSEP_DEMO_PENDANT:-1}" = "0" ]; then
      release+=(--no-pendant)
      echo "DEMO: a day without the pendant (TINYSEP_DEMO_PENDANT=0, simulator --no-pendant): only the room sensors"
      echo "  watch; Anna's collapse at 14:02 is noticed by the inactivity alert once the bathroom's limit has passed"
    else
      echo "DEMO: Anna wears her pendant (person node $(persons)): her collapse at 14:02 is a FALL alert within seconds;"
      echo "  TINYSEP_DEMO_PENDANT=0 plays the day without it (the room sensors' inactivity alert is the fallback)"
    fi
    exec java -jar "$jar" --lockstep --wait-platform "${TINYSEP_DEMO_WAIT:-60}" \
      --from "${TINYSEP_DEMO_FROM:-06:30}" --until "${TINYSEP_DEMO_UNTIL:-23:00}" \
      --progress 120 ${release[@]+"${release[@]}"} --sync-key "$demo/var/sync.key" \
      --amica-port "$(cfg_value "$demo_etc/org.tinysep.amica.busradio.udp.cfg" port 47011)" \
      --sunspot-port "$(cfg_value "$demo_etc/org.tinysep.sunspot.busradio.cfg" udpPort 47012)" \
      --sync-port "$(cfg_value "$demo_etc/org.tinysep.timecontroller.cfg" syncPort 47020)" ;;
  ports-ours)
    demo="$dist"; case "$demo" in /*) ;; *) demo="$PWD/$demo" ;; esac
    ports_ours "${3:?$usage}" "${TINYSEP_DEMO_WAIT:-60}" ;;
  *) echo "$usage" >&2; exit 2 ;;
esac
