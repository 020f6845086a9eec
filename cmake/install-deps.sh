#!/usr/bin/env bash
# Installs qm-atms' build dependencies from Debian 12 packages. Idempotent: packages already
# present are skipped, and apt is not touched at all when nothing is missing.
# Works as root, or through sudo when not root.
#   bash cmake/install-deps.sh        everything: the executable, every test, benchmark and fuzz target
#   bash cmake/install-deps.sh run    only what configuring the tree and building qm-atms need
#                                     (`make run`): no clang, no browser, so a fresh machine gets
#                                     its first answer sooner
set -euo pipefail

run_packages=(
  build-essential cmake pkg-config
  libboost-dev libboost-graph-dev      # Spirit X3 (header-only) and Boost.Graph
  libeigen3-dev                        # geometry
  libfcl-dev libccd-dev                # collision and distance
  libedit-dev                          # line editing and history in the interactive mode (-i)
  libcli11-dev                         # every command's options (CLI11, header-only)
  libgraphviz-dev                      # envision --svg: Graphviz's library lays out and draws the graph
  doctest-dev                          # unit tests (small; the configure step looks for it)
  nlohmann-json3-dev                   # the tests read the program's JSON (header-only; configure looks for it)
  libbenchmark-dev                     # bench/ (small; the configure step looks for it)
)
test_packages=(
  clang-16 libclang-rt-16-dev          # the sanitizer and libFuzzer tree (clang 16: C++20 lambdas may capture structured bindings)
  llvm-16                              # its llvm-symbolizer, for the sanitizers' stack traces
  chromium chromium-driver python3-selenium  # the explorer page's test in a headless browser
)

case "${1:-all}" in
  run) packages=("${run_packages[@]}") ;;
  all) packages=("${run_packages[@]}" "${test_packages[@]}") ;;
  *) echo "usage: bash cmake/install-deps.sh [run|all]" >&2; exit 2 ;;
esac

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
