#!/usr/bin/env bash
# Installs qm-atms' build dependencies from Debian 12 packages. Idempotent: packages already
# present are skipped, and apt is not touched at all when nothing is missing.
# Works as root, or through sudo when not root.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libboost-dev libboost-graph-dev      # Spirit X3 (header-only) and Boost.Graph
  libeigen3-dev                        # geometry
  libfcl-dev libccd-dev                # collision and distance
  doctest-dev                          # unit tests
  libbenchmark-dev                     # bench/
  clang libclang-rt-14-dev             # libFuzzer targets and sanitizer runtimes
  chromium chromium-driver python3-selenium  # the explorer page's test in a headless browser
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all dependencies present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1; then
  SUDO=(sudo)
else
  echo "install-deps: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -qq
"${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
