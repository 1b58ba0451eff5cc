#!/usr/bin/env bash
# Installs what the build and tests need beyond the JDK and Maven. Idempotent; safe to run on every build.
#   java, maven  - build
#   iproute2     - ss: the demo checks which process holds its UDP ports (scripts/demo-flat.sh ports-ours)
#   socat        - pseudo-terminal pairs for the serial bus radio tests (docs/build-notes.md: jSerialComm on a pty)
#   chromium, chromium-driver - headless browser for the web console's browser test (docs/web-api.md)
#   gammu-smsd   - SMS daemon driving a GSM modem; its dummy modem for the SMS channel tests (docs/alerts-by-phone.md)
#   gradle       - the second build (Debian's Gradle 4.4.1: build.gradle, README "Gradle build")
#   mosquitto    - real MQTT broker for the MQTT bridge tests (testsupport/org.tinysep.testsupport.mqtt, docs/mqtt.md)
set -euo pipefail
need=()
command -v java >/dev/null || need+=(openjdk-17-jdk-headless)
command -v mvn >/dev/null || need+=(maven)
command -v socat >/dev/null || need+=(socat)
command -v ss >/dev/null || need+=(iproute2)
command -v gammu-smsd >/dev/null || [ -x /usr/bin/gammu-smsd ] || need+=(gammu-smsd)
command -v gradle >/dev/null || need+=(gradle)
command -v chromium >/dev/null || need+=(chromium)
command -v chromedriver >/dev/null || need+=(chromium-driver)
command -v mosquitto >/dev/null || [ -x /usr/sbin/mosquitto ] || need+=(mosquitto)
if [ ${#need[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "Missing packages: ${need[*]} - install them (apt-get update && apt-get install ${need[*]}) and run again." >&2
    exit 1
  fi
  echo "Installing ${need[*]} ..."
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi
java_major=$(java -version 2>&1 | sed -n 's/.*version "\([0-9]*\).*/\1/p' | head -1)
if [ "${java_major:-0}" -lt 17 ]; then
  echo "Java 17 or newer is needed, found ${java_major:-none}." >&2
  exit 1
fi
if ! command -v socat >/dev/null; then
  echo "socat is still missing after installation." >&2
  exit 1
fi
