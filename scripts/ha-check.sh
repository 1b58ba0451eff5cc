#!/usr/bin/env bash
# Home Assistant check of the MQTT bridge's discovery. Opt-in: NOT run by ./test.sh.
#
#   scripts/ha-check.sh            (from anywhere; needs mosquitto, python3 >= 3.11, network to PyPI the first time)
#
# 1. Home Assistant 2024.3 from PyPI in a virtual environment ($HA_CHECK_DIR/venv, default
#    ${TMPDIR:-/tmp}/tinysep-ha-check/venv; kept between runs), with the requirements of the integrations it loads
#    here (paho-mqtt 1.6.1 for MQTT, the frontend and its dependencies), installed by this script so Home Assistant
#    itself never runs pip: it starts with --skip-pip.
# 2. Debian's Mosquitto on a free port of 127.0.0.1 (anonymous, no persistence).
# 3. The real TinySEP distribution (runtime/org.tinysep.launcher/target/tinysep; built with mvn -o package if
#    missing) playing the demo flat (scripts/demo-flat.sh: flat A, 20 AmICA + 3 Sun SPOT nodes, simulated in
#    lock-step time for 06:30-08:00) in its own throwaway folder, every port moved to a free one, with its MQTT
#    bridge configured for that Mosquitto: it publishes the retained Home Assistant discovery configs.
# 4. Home Assistant with a generated configuration folder: configuration.yaml (http on a free port of 127.0.0.1)
#    and the MQTT integration as a config entry written to .storage/core.config_entries before the start (the
#    storage format of Home Assistant 2024.3: version 1, the ConfigEntry.as_dict() fields; data broker/port/
#    discovery), so no UI is needed.
# 5. Waits until Home Assistant has set up one entity per discovery config, stops it in order (SIGTERM: it writes
#    its registries) and reads .storage/core.entity_registry: prints every entity of the MQTT platform with its
#    component type, device class and unique id, and checks that each discovery config's unique id is there.
# Exit status 0 when every discovered entity is registered. Every process it starts is stopped by its PID.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
work="${HA_CHECK_DIR:-${TMPDIR:-/tmp}/tinysep-ha-check}"
venv="$work/venv"
run="$work/run"
dist="$repo/runtime/org.tinysep.launcher/target/tinysep"
wait_s="${HA_CHECK_WAIT:-300}"
pids=()

log() { echo "ha-check: $*"; }
stop_all() {
  for ((i=${#pids[@]}-1; i>=0; i--)); do
    kill "${pids[i]}" 2>/dev/null || true
    for _ in $(seq 1 100); do kill -0 "${pids[i]}" 2>/dev/null || break; sleep 0.2; done
    kill -9 "${pids[i]}" 2>/dev/null || true
  done
}
trap stop_all EXIT
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'; }
wait_for() { # wait_for <seconds> <what> <command...>: polls the command every second
  local limit=$1 what=$2; shift 2
  for _ in $(seq 1 "$limit"); do "$@" && return 0; sleep 1; done
  log "FAILED: no $what within $limit s"; return 1
}

# 1. Home Assistant in a virtual environment
mkdir -p "$work"
# The requirements of the integrations Home Assistant loads here (mqtt and what it and the frontend depend on), at
# the versions of their 2024.3 manifests: installed now, so Home Assistant starts with --skip-pip.
ha_requirements=('paho-mqtt==1.6.1' 'home-assistant-frontend==20240307.0' 'janus==1.0.0' 'Pillow==10.2.0'
  'psutil-home-assistant==0.0.1' 'securetar==2024.2.1' 'SQLAlchemy==2.0.27' 'fnv-hash-fast==0.5.0')
if [ ! -x "$venv/bin/hass" ] || ! "$venv/bin/python" -c 'import paho.mqtt, janus, PIL, hass_frontend, sqlalchemy' 2>/dev/null; then
  log "installing homeassistant==2024.3.* and its MQTT/frontend requirements into $venv (pip log: $work/pip.log)"
  python3 -m venv "$venv"
  { "$venv/bin/pip" install 'homeassistant==2024.3.*' \
    && "$venv/bin/pip" install -c "$("$venv/bin/python" -c 'import homeassistant, os; print(os.path.dirname(homeassistant.__file__))')/package_constraints.txt" \
      "${ha_requirements[@]}"; } > "$work/pip.log" 2>&1 \
    || { tail -20 "$work/pip.log"; log "FAILED: pip install (whole log: $work/pip.log)"; exit 1; }
fi
log "$("$venv/bin/python" -c 'from homeassistant.const import __version__ as v; print("Home Assistant", v)'), python $("$venv/bin/python" -c 'import platform; print(platform.python_version())')"

# the distribution and the simulator
if [ ! -x "$dist/bin/tinysep" ] || ! ls "$repo"/simulator/target/org.tinysep.simulator-*.jar >/dev/null 2>&1; then
  log "building the distribution and the simulator (mvn -o package; log: $work/build.log)"
  (cd "$repo" && mvn -B -o -q -DskipTests package -pl runtime/org.tinysep.launcher,simulator -am > "$work/build.log" 2>&1) \
    || { tail -20 "$work/build.log"; log "FAILED: build"; exit 1; }
fi

rm -rf "$run"
mkdir -p "$run/mosquitto" "$run/ha/.storage"

# 2. Mosquitto
mport=$(free_port)
cat > "$run/mosquitto/mosquitto.conf" <<EOF
listener $mport 127.0.0.1
socket_domain ipv4
user $(id -un)
allow_anonymous true
persistence false
log_dest file $run/mosquitto/mosquitto.log
EOF
mosquitto_bin=$(command -v mosquitto || echo /usr/sbin/mosquitto)
"$mosquitto_bin" -c "$run/mosquitto/mosquitto.conf" > "$run/mosquitto/out.log" 2>&1 &
pids+=($!)
wait_for 30 "Mosquitto on 127.0.0.1:$mport" bash -c "echo > /dev/tcp/127.0.0.1/$mport" 2>/dev/null
log "Mosquitto on 127.0.0.1:$mport"

# 3. TinySEP: the demo flat, ports moved, the MQTT bridge pointed at the broker
demo="$run/tinysep"
"$repo/scripts/demo-flat.sh" prepare "$dist" "$demo"
etc="$demo/home/etc"
{ echo; echo "# ha-check: a free port"; echo "org.osgi.service.http.port=$(free_port)"; echo "org.apache.felix.http.host=127.0.0.1"; } >> "$etc/org.apache.felix.http.cfg"
{ echo; echo "port=$(free_port)"; } >> "$etc/org.tinysep.amica.busradio.udp.cfg"
{ echo; echo "udpPort=$(free_port)"; } >> "$etc/org.tinysep.sunspot.busradio.cfg"
{ echo; echo "syncPort=$(free_port)"; } >> "$etc/org.tinysep.timecontroller.cfg"
cat > "$etc/org.tinysep.mqtt.cfg" <<EOF
brokerUrl=tcp://127.0.0.1:$mport
flatId=flat-a
# the check's broker lets anyone in (only with the override; Home Assistant's plain ON/OFF is unsigned)
allowAnonymous=true
commands.actuators=unsigned
queueDir=$demo/var/mqtt
EOF
(cd "$dist" && TINYSEP_DAEMON=1 exec bin/tinysep --home "$demo/home" --var "$demo/var" > "$run/tinysep.log" 2>&1) &
pids+=($!)
log "TinySEP (the real distribution, demo flat A) starting; log: $run/tinysep.log"
TINYSEP_DEMO_FROM=06:30 TINYSEP_DEMO_UNTIL=08:00 TINYSEP_DEMO_DELAY=1 TINYSEP_DEMO_WAIT=120 \
  "$repo/scripts/demo-flat.sh" simulate "$dist" "$demo" > "$run/simulator.log" 2>&1 \
  || { tail -5 "$run/simulator.log"; log "FAILED: the simulator (log: $run/simulator.log)"; exit 1; }
log "simulated 06:30-08:00 of flat A: $(grep -E '^done:' "$run/simulator.log" | tail -1)"

configs() { # the retained discovery configs on the broker, one "topic payload" per line (paho-mqtt of the venv)
  "$venv/bin/python" - "$mport" <<'PY'
import sys, time, paho.mqtt.client as mqtt
seen = {}
def on_message(client, userdata, m):
    if m.retain and m.topic.endswith("/config") and m.payload:
        seen[m.topic] = m.payload.decode()
c = mqtt.Client("ha-check-reader")
c.on_message = on_message
c.connect("127.0.0.1", int(sys.argv[1]))
c.subscribe("homeassistant/#", qos=1)
c.loop_start()
time.sleep(3)
c.loop_stop()
c.disconnect()
for topic in sorted(seen):
    print(topic, seen[topic])
PY
}
count=0
for _ in $(seq 1 30); do # until the bridge has published all (the number stops growing)
  n=$(configs | wc -l)
  [ "$n" -gt 0 ] && [ "$n" -eq "$count" ] && break
  count=$n
  sleep 2
done
configs > "$run/discovery.txt"
count=$(wc -l < "$run/discovery.txt")
[ "$count" -gt 0 ] || { log "FAILED: TinySEP published no discovery config"; tail -20 "$run/tinysep.log"; exit 1; }
log "TinySEP published $count retained discovery configs under homeassistant/"

# 4. Home Assistant, MQTT configured without the UI
hport=$(free_port)
cat > "$run/ha/configuration.yaml" <<EOF
homeassistant:
  name: TinySEP check
  time_zone: UTC
  unit_system: metric
  latitude: 0
  longitude: 0
  elevation: 0
http:
  server_host: 127.0.0.1
  server_port: $hport
logger:
  default: warning
  logs:
    homeassistant.components.mqtt.discovery: info
    homeassistant.components.mqtt.client: info
EOF
cat > "$run/ha/.storage/core.config_entries" <<EOF
{"version": 1, "minor_version": 1, "key": "core.config_entries", "data": {"entries": [
  {"entry_id": "tinysepcheckmqtt0000000000000001", "version": 1, "minor_version": 1, "domain": "mqtt",
   "title": "127.0.0.1", "data": {"broker": "127.0.0.1", "port": $mport, "discovery": true},
   "options": {}, "pref_disable_new_entities": false, "pref_disable_polling": false, "source": "user",
   "unique_id": null, "disabled_by": null}]}}
EOF
"$venv/bin/hass" --config "$run/ha" --skip-pip --log-file "$run/ha/home-assistant.log" > "$run/ha/out.log" 2>&1 &
ha_pid=$!
pids+=($ha_pid)
log "Home Assistant starting (config $run/ha, http 127.0.0.1:$hport, log $run/ha/home-assistant.log)"
found() {
  local n
  n=$(grep -c 'Found new component' "$run/ha/home-assistant.log" 2>/dev/null) || true
  [ "${n:-0}" -ge "$count" ]
}
wait_for "$wait_s" "discovery of all $count configs by Home Assistant" found \
  || { tail -30 "$run/ha/home-assistant.log"; exit 1; }
log "Home Assistant found all $count discovery configs; letting it set the entities up, then stopping it"
sleep 15 # entity platforms are set up after discovery; the registry is written when Home Assistant stops
kill "$ha_pid"
for _ in $(seq 1 300); do kill -0 "$ha_pid" 2>/dev/null || break; sleep 0.2; done

# 5. what Home Assistant registered
"$venv/bin/python" - "$run/ha/.storage/core.entity_registry" "$run/discovery.txt" <<'EOF'
import json, sys
registry = json.load(open(sys.argv[1]))["data"]["entities"]
mqtt = sorted((e for e in registry if e["platform"] == "mqtt"), key=lambda e: e["entity_id"])
print(f"Home Assistant registered {len(mqtt)} MQTT entities:")
print(f"  {'component':<14} {'device class':<13} {'unique id':<40} entity id")
for e in mqtt:
    component = e["entity_id"].split(".")[0]
    device_class = e.get("device_class") or e.get("original_device_class") or "-"
    print(f"  {component:<14} {device_class:<13} {e['unique_id']:<40} {e['entity_id']}")
wanted = {}
for line in open(sys.argv[2]):
    topic, payload = line.rstrip("\n").split(" ", 1)
    wanted[json.loads(payload)["unique_id"]] = topic.split("/")[1]
have = {e["unique_id"]: e["entity_id"].split(".")[0] for e in mqtt}
missing = sorted(u for u in wanted if u not in have)
wrong = sorted(u for u in wanted if u in have and have[u] != wanted[u])
print(f"discovery configs: {len(wanted)}; registered: {len(wanted) - len(missing)}; missing: {missing or 'none'};"
      f" registered with another component: {wrong or 'none'}")
sys.exit(1 if missing or wrong else 0)
EOF
