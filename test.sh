#!/usr/bin/env bash
# Runs every unit and integration test (JUnit 5 + Pax Exam in a real Felix) on a fresh machine. The tests read
# nothing outside this repository: their data is in data/ (README.md, "Tests and their data").
# Resume after a failure with Maven's hint, ./test.sh -rf :<module>: Maven 3 would look for the earlier modules
# in ~/.m2, which this script never installs into, so it runs "-pl <that module and every later one> -am" instead
# (the earlier modules those need are built again in the same reactor, and their tests run again).
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
args=()
from=""
while (($#)); do
  case "$1" in
    -rf|--resume-from) from="${2:?$1 needs a module, e.g. -rf :org.tinysep.simulator}"; shift 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
if [[ -z "$from" ]]; then
  exec mvn -B verify ${args[@]+"${args[@]}"}
fi
# the reactor order, one groupId:artifactId a line, from Maven's own "----< g:a >----" headers
if ! validated=$(mvn -B validate 2>&1); then
  echo "$validated" >&2
  exit 1
fi
order=$(sed -n 's/^\[INFO\] -*< \([^ ]*\) >-*$/\1/p' <<<"$validated")
wanted="${from##*:}"
later=$(awk -v a="$wanted" -F: '$2 == a {on = 1} on {printf "%s:%s,", $1, $2}' <<<"$order")
if [[ -z "$later" ]]; then
  echo "test.sh: no module '$from' in this build; give one of:" >&2
  sed 's/^[^:]*:/  :/' <<<"$order" >&2
  exit 2
fi
names=${later%,}
echo "test.sh: resuming from $from: ${names//,/ } and the modules they need (built again here, their tests" \
  "included: test.sh does not install into ~/.m2)"
exec mvn -B verify ${args[@]+"${args[@]}"} -pl "${later%,}" -am
