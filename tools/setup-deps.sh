#!/usr/bin/env bash
# Install the Debian packages the build needs, only those that are missing.
#   setup-deps.sh            what the build and make test need
#   setup-deps.sh accuracy   also what make accuracy / make validate need
#                            (gnuplot-nox draws the report's plots)
set -eu
pkgs="build-essential cmake git pkg-config dpkg-dev openmpi-bin libopenmpi-dev
      libfftw3-dev libpng-dev libjpeg-dev zlib1g-dev python3 ccache"
for target in "$@"; do
  case "$target" in
    accuracy) pkgs="$pkgs gnuplot-nox" ;;
    *) echo "setup-deps.sh: unknown target '$target' (known: accuracy)" >&2; exit 2 ;;
  esac
done
missing=""
for p in $pkgs; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' \
    || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "setup: installing$missing"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends $missing
