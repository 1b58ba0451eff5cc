#!/usr/bin/env bash
# Builds TinySEP and runs its distribution in the foreground with the interactive Gogo shell.
# Extra arguments go to the launcher:  ./run.sh --daemon   (no shell; stops on SIGTERM / Ctrl-C)
# Environment: SKIP_BUILD=1 skips the Maven build; TINYSEP_DEMO=0 skips the simulated demo flat; JAVA_OPTS is passed to java
#   (e.g. JAVA_OPTS=-Dorg.slf4j.simpleLogger.defaultLogLevel=debug).
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
# State (drivers list, house, mail spool, framework cache) lives in <repo>/var, outside target/: `mvn clean` keeps it.
# TINYSEP_VAR=<dir> puts it elsewhere.
var="${TINYSEP_VAR:-$repo/var}"
mkdir -p "$var"
cd runtime/org.tinysep.launcher/target/tinysep
# No hardware configured: the simulated demo flat runs against the platform (scripts/demo-flat.sh; TINYSEP_DEMO=0
# turns it off). The simulator waits for the platform, plays one virtual day in lock-step, and then exits.
if "$repo/scripts/demo-flat.sh" wanted "$PWD"; then
  "$repo/scripts/demo-flat.sh" prepare "$PWD" "$var"
  echo "No hardware configured: the demo flat (simulator/, flat A) plays a virtual day 06:30-23:00 in a few seconds"
  echo "once the platform is up; simulator output: $var/simulator.log. TINYSEP_DEMO=0 ./run.sh skips it."
  "$repo/scripts/demo-flat.sh" simulate "$PWD" > "$var/simulator.log" 2>&1 &
  # a simulated day makes tens of thousands of events in seconds: keep them off the console (they are in the event
  # log: tinysep:events ..., var/log/events-*.log); warnings, the mail text and the rest of the log still show
  demo_opts="-Dorg.slf4j.simpleLogger.log.tinysep.events=warn"
fi
# shellcheck disable=SC2086 # JAVA_OPTS is a list of options; given later, it wins over demo_opts
exec java ${demo_opts:-} ${JAVA_OPTS:-} -jar tinysep.jar --var "$var" "$@"
