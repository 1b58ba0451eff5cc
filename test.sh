#!/usr/bin/env bash
# Runs every unit and integration test (JUnit 5 + Pax Exam in a real Felix) on a fresh machine.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
exec mvn -B verify "$@"
