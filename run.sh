#!/usr/bin/env bash
# Builds TinySEP and runs its distribution in the foreground with the interactive Gogo shell.
# Extra arguments go to the launcher:  ./run.sh --daemon   (no shell; stops on SIGTERM / Ctrl-C)
# Environment: SKIP_BUILD=1 skips the Maven build; TINYSEP_DEMO=0 skips the simulated demo flat; JAVA_OPTS is passed to java
#   (e.g. JAVA_OPTS=-Dorg.slf4j.simpleLogger.defaultLogLevel=debug), after the distribution's etc/jvm.options (the
#   gateway's JVM options; TINYSEP_JVM_OPTIONS=none: the JVM's defaults).
set -euo pipefail
cd "$(dirname "$0")"
if [[ "${SKIP_BUILD:-0}" != "1" ]]; then
  scripts/install-deps.sh
  # one line per module as Maven builds it (about 40 s the first time); the whole log: target/build.log
  mkdir -p target
  echo "Building TinySEP (mvn -B -DskipTests package; log: target/build.log)"
  build_start=$SECONDS
  set +e
  mvn -B -DskipTests package 2>&1 | tee target/build.log \
    | sed -un 's/^\[INFO\] Building \(.*\) [0-9][^ ]* *\[\([0-9]*\/[0-9]*\)\]$/  [\2] \1/p'
  build_status=${PIPESTATUS[0]}
  set -e
  if [[ $build_status -ne 0 ]]; then
    grep -E '^\[ERROR\]' target/build.log | head -40 >&2
    echo "Build failed (mvn exit code $build_status); the whole log: target/build.log" >&2
    exit "$build_status"
  fi
  echo "Built in $((SECONDS - build_start)) s"
fi
repo=$(pwd)
# TinySEP's state (house plan, alert texts, settings, secrets) is for this user only: folders rwx------, files
# rw------- (docs/backup.md, "File modes"), also those the framework and the demo create
umask 077
# State (drivers list, house, mail spool, framework cache) lives in <repo>/var, outside target/: `mvn clean` keeps it.
# TINYSEP_VAR=<dir> puts it elsewhere.
var="${TINYSEP_VAR:-$repo/var}"
cd runtime/org.tinysep.launcher/target/tinysep
# etc/ files an older demo wrote into the distribution (they froze the clock in EXTERNAL mode) are removed
"$repo/scripts/demo-flat.sh" forget-old-demo "$PWD"
# No hardware configured: the simulated demo flat runs against the platform (scripts/demo-flat.sh; TINYSEP_DEMO=0
# turns it off), in its own throwaway state: a demo home (its etc/) and state folder in TINYSEP_DEMO_DIR (default
# <repo>/target/demo), re-created at every demo start. Neither var/ nor the distribution's etc/ is written.
# The simulator waits for the platform, plays one virtual day in lock-step, returns the clock to real time and exits.
launch=(--var "$var")
if "$repo/scripts/demo-flat.sh" wanted "$PWD"; then
  demo="${TINYSEP_DEMO_DIR:-$repo/target/demo}"
  "$repo/scripts/demo-flat.sh" prepare "$PWD" "$demo"
  launch=(--home "$demo/home" --var "$demo/var")
  echo "DEMO: no hardware is configured, so this is the demo flat (simulator/, flat A): a virtual day 06:30-23:00"
  echo "  plays in a few seconds once the platform is up, then the clock returns to real time. The demo has its own"
  echo "  state in $demo, thrown away at the next demo start; your state folder $var and"
  echo "  the distribution's etc/ are not used. To run for real: TINYSEP_DEMO=0 ./run.sh (or configure hardware, e.g."
  echo "  etc/org.tinysep.amica.busradio.serial-usb0.cfg). Simulator output: $demo/simulator.log"
  (
    if "$repo/scripts/demo-flat.sh" simulate "$PWD" "$demo" > "$demo/simulator.log" 2>&1; then
      echo "DEMO: the simulated day is played; the clock follows real time again ($(grep -E "^done:" "$demo/simulator.log" | tail -1))"
    else
      echo "DEMO: the simulator FAILED (exit $?); the demo day did not run. Its last words ($demo/simulator.log):"
      tail -3 "$demo/simulator.log" | sed 's/^/  /'
    fi >&2
  ) &
  # a simulated day makes tens of thousands of events in seconds: keep them off the console (they are in the event
  # log: tinysep:events ..., the demo's log/); warnings, the mail text and the rest of the log still show
  demo_opts="-Dorg.slf4j.simpleLogger.log.tinysep.events=warn"
else
  mkdir -p "$var"
fi
# the web console's address (etc/org.apache.felix.http.cfg, docs/web-api.md) and how to get in
http_cfg="${demo:+$demo/home/}etc/org.apache.felix.http.cfg"
http_host=$(sed -n 's/^[[:space:]]*org\.apache\.felix\.http\.host[[:space:]]*[=:][[:space:]]*\([^[:space:]]*\).*/\1/p' "$http_cfg" 2>/dev/null | tail -1 || true)
http_port=$(sed -n 's/^[[:space:]]*org\.osgi\.service\.http\.port[[:space:]]*[=:][[:space:]]*\([0-9]*\).*/\1/p' "$http_cfg" 2>/dev/null | tail -1 || true)
echo "Web console: http://${http_host:-127.0.0.1}:${http_port:-8080}/ - set a password first, in the TinySEP shell:"
echo "  tinysep:web-password installer <password>   (and: tinysep:web-password caregiver <password>)"
# The gateway's JVM options (heap cap, serial GC, C1 only, ...: etc/jvm.options, figures in benchmarks/RESULTS.md)
# come from the distribution's launcher script bin/tinysep; JAVA_OPTS is given after them, so it wins over them and
# over demo_opts (TINYSEP_JVM_OPTIONS=none: the JVM's own defaults)
JAVA_OPTS="${demo_opts:-} ${JAVA_OPTS:-}" exec bin/tinysep "${launch[@]}" "$@"
