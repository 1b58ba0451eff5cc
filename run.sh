#!/usr/bin/env bash
# Builds TinySEP and runs its distribution in the foreground with the interactive Gogo shell.
# Extra arguments go to the launcher:  ./run.sh --daemon   (no shell; stops on SIGTERM / Ctrl-C)
# Environment: SKIP_BUILD=1 skips the Maven build (FORCE_BUILD=1 builds even when no source changed); TINYSEP_DEMO=0 skips the simulated demo flat; JAVA_OPTS is passed to java
#   (e.g. JAVA_OPTS=-Dorg.slf4j.simpleLogger.defaultLogLevel=debug), after the distribution's etc/jvm.options (the
#   gateway's JVM options; TINYSEP_JVM_OPTIONS=none: the JVM's defaults).
set -euo pipefail
cd "$(dirname "$0")"
# Builds only when a source, pom or script is newer than target/build.stamp (the last good build):
# FORCE_BUILD=1 always builds, SKIP_BUILD=1 never does
dist_jar=runtime/org.tinysep.launcher/target/tinysep/tinysep.jar
needs_build() {
  [[ "${FORCE_BUILD:-0}" == "1" ]] && return 0
  [[ -f target/build.stamp && -f $dist_jar ]] || return 0
  [[ -n "$(find . \( -name target -o -name var -o -name .git -o -name node_modules \) -prune -o \
      \( -name pom.xml -o -path '*/src/*' \) -type f -newer target/build.stamp -print -quit)" ]]
}
if [[ "${SKIP_BUILD:-0}" != "1" ]] && needs_build; then
  scripts/install-deps.sh
  # one line per module as Maven builds it; the whole log: target/build.log
  mkdir -p target
  echo "Building TinySEP (mvn -B -DskipTests package, a few minutes on a 2-core machine; log: target/build.log;"
  echo "  SKIP_BUILD=1 ./run.sh starts without building)"
  build_start=$SECONDS
  touch target/build.stamp.next # sources changed while Maven runs are newer than it: the next start builds again
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
  mv -f target/build.stamp.next target/build.stamp
  echo "Built in $((SECONDS - build_start)) s"
elif [[ "${SKIP_BUILD:-0}" != "1" ]]; then
  echo "No source changed since the last build (target/build.stamp): not building (FORCE_BUILD=1 builds anyway)"
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
setting_password=0
for a in "$@"; do [[ "$a" == --web-password ]] && setting_password=1; done
if "$repo/scripts/demo-flat.sh" wanted "$PWD" && [[ $setting_password == 1 ]]; then
  # ./run.sh --web-password ROLE: the demo's password (kept across demo starts), no demo day
  demo="${TINYSEP_DEMO_DIR:-$repo/target/demo}"
  [[ -d "$demo/home" ]] || "$repo/scripts/demo-flat.sh" prepare "$PWD" "$demo" > /dev/null
  exec bin/tinysep --home "$demo/home" --var "$demo/var" "$@"
elif "$repo/scripts/demo-flat.sh" wanted "$PWD"; then
  demo="${TINYSEP_DEMO_DIR:-$repo/target/demo}"
  "$repo/scripts/demo-flat.sh" prepare "$PWD" "$demo"
  launch=(--home "$demo/home" --var "$demo/var")
  demo_until="${TINYSEP_DEMO_UNTIL:-23:00}"
  echo "DEMO: no hardware is configured, so this is the demo flat (simulator/, flat A): a virtual day"
  echo "  ${TINYSEP_DEMO_FROM:-06:30}-$demo_until plays in a few seconds once the platform is up; then the platform's clock stays"
  echo "  on the demo day (tinysep:time real returns to real time; TINYSEP_DEMO_RELEASE=1 does so at the end). The demo"
  echo "  has its own state in $demo, thrown away at the next demo start (web passwords are kept);"
  echo "  your state folder $var and the distribution's etc/ are not used. To run for real:"
  echo "  TINYSEP_DEMO=0 ./run.sh (or configure hardware, e.g. etc/org.tinysep.amica.busradio.serial-usb0.cfg)."
  echo "  Simulator output: $demo/simulator.log"
  platform_pid=$$ # exec below: the platform keeps this shell's process id
  (
    "$repo/scripts/demo-flat.sh" simulate "$PWD" "$demo" "$platform_pid" > "$demo/simulator.log" 2>&1 &
    sim=$!
    # the platform stopped early (stop 0, Ctrl-C): the simulator stops with it, silently
    while kill -0 "$sim" 2>/dev/null; do
      if ! kill -0 "$platform_pid" 2>/dev/null; then
        kill "$sim" 2>/dev/null; wait "$sim" 2>/dev/null; exit 0
      fi
      sleep 1
    done
    status=0; wait "$sim" || status=$?
    kill -0 "$platform_pid" 2>/dev/null || exit 0
    if [[ $status -eq 0 ]]; then
      if [[ "${TINYSEP_DEMO_RELEASE:-0}" == "1" ]]; then
        echo "DEMO: the simulated day is played; the clock follows real time again ($(grep -E "^done:" "$demo/simulator.log" | tail -1))"
      else
        echo "DEMO: the simulated day is played up to $demo_until; the clock stays there (tinysep:time real: back to real time)"
      fi
    elif [[ $status -eq 3 ]]; then
      echo "DEMO: the demo day was NOT sent:"
      grep -E '^(demo flat|  )' "$demo/simulator.log" | sed 's/^/  /'
    else
      echo "DEMO: the simulator FAILED (exit $status); the demo day did not run. Its last words ($demo/simulator.log):"
      tail -3 "$demo/simulator.log" | sed 's/^/  /'
    fi >&2
  ) &
  # a simulated day makes tens of thousands of events in seconds: keep them off the console (they are in the event
  # log: tinysep:events ..., the demo's log/); so are the texts of the mails the demo does not send (logger tinysep.mail):
  # the console gets one line per alert (tinysep:alerts, the web console and the event log have the rest)
  demo_opts="-Dorg.slf4j.simpleLogger.log.tinysep.events=warn -Dorg.slf4j.simpleLogger.log.tinysep.mail=error"
else
  mkdir -p "$var"
fi
# the web console's address is said by the platform once its HTTP server has bound (WebConsoleLine), with the port
# it really has
# The gateway's JVM options (heap cap, serial GC, C1 only, ...: etc/jvm.options, figures in benchmarks/RESULTS.md)
# come from the distribution's launcher script bin/tinysep; JAVA_OPTS is given after them, so it wins over them and
# over demo_opts (TINYSEP_JVM_OPTIONS=none: the JVM's own defaults)
JAVA_OPTS="${demo_opts:-} ${JAVA_OPTS:-}" exec bin/tinysep "${launch[@]}" "$@"
