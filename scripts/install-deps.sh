#!/usr/bin/env bash
# Installs every build and test dependency of ncc from Debian 12 packages.
# Idempotent; needs root (or sudo). Nothing is downloaded outside Debian's archive.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PACKAGES=(
  build-essential cmake ninja-build pkg-config git python3
  antlr4 libantlr4-runtime-dev
  libeigen3-dev libabsl-dev libcli11-dev libtomlplusplus-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The speed benchmark compares against LinuxCNC's rs274 interpreter; it is optional
# (bench/ prints "peer unavailable" without it), so a failure here is not fatal.
if [ "${NCC_WITH_PEER:-0}" = "1" ]; then
  dpkg-query -W -f='${Status}' linuxcnc-uspace 2>/dev/null | grep -q "install ok installed" || \
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq linuxcnc-uspace || \
    echo "install-deps: linuxcnc-uspace not installed; benchmarks will run without the rs274 peer" >&2
fi
