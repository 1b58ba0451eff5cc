#!/usr/bin/env bash
# Builds TinySEP and runs its distribution in the foreground with the interactive Gogo shell.
# Extra arguments go to the launcher:  ./run.sh --daemon   (no shell; stops on SIGTERM / Ctrl-C)
# Environment: SKIP_BUILD=1 skips the Maven build; TINYSEP_DEMO=0 skips the simulated demo flat; JAVA_OPTS is passed to java
#   (e.g. JAVA_OPTS=-Dorg.slf4j.simpleLogger.defaultLogLevel=debug).
set -euo pipefail
cd "$(dirname "$0")"
if [[ "${SKIP_BUILD:-0}" != "1" ]]; then
  scripts/install-deps.sh
  mvn -B -q -DskipTests package
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
fi
# shellcheck disable=SC2086 # JAVA_OPTS is a list of options
exec java ${JAVA_OPTS:-} -jar tinysep.jar --var "$var" "$@"
