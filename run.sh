#!/usr/bin/env bash
# Builds TinySEP and runs its distribution in the foreground with the interactive Gogo shell.
# Extra arguments go to the launcher:  ./run.sh --daemon   (no shell; stops on SIGTERM / Ctrl-C)
# Environment: SKIP_BUILD=1 skips the Maven build; JAVA_OPTS is passed to java
#   (e.g. JAVA_OPTS=-Dorg.slf4j.simpleLogger.defaultLogLevel=debug).
set -euo pipefail
cd "$(dirname "$0")"
if [[ "${SKIP_BUILD:-0}" != "1" ]]; then
  scripts/install-deps.sh
  mvn -B -q -DskipTests package
fi
cd runtime/org.tinysep.launcher/target/tinysep
# shellcheck disable=SC2086 # JAVA_OPTS is a list of options
exec java ${JAVA_OPTS:-} -jar tinysep.jar "$@"
