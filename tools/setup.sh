#!/usr/bin/env bash
# Installs what gmr needs from Debian's packages, if missing (apt-get as root; nothing else is
# downloaded). Used by tools/demo.sh and tools/test.sh.
set -euo pipefail
pkgs=(cmake g++ make ninja-build ccache lld libz3-dev librapidcheck-dev libgtest-dev libgmock-dev graphviz
      libgraphviz-dev nlohmann-json3-dev libcli11-dev libtinyxml2-dev libbenchmark-dev libcgal-dev libcgal-demo pkg-config
      clang-format)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "gmr setup: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then SUDO="sudo"; else
    echo "gmr setup: please install as root: apt-get install ${missing[*]}" >&2; exit 2; fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get install -y --no-install-recommends "${missing[@]}" >/dev/null ||
  { $SUDO apt-get update >/dev/null && $SUDO apt-get install -y --no-install-recommends "${missing[@]}" >/dev/null; }
