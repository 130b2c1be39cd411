#!/usr/bin/env bash
# Install the Debian packages the build and the tests need, only those that
# are missing (libfftw3-dev: tools/pd_exact; gnuplot-nox: the accuracy
# report's plots, drawn by accuracy.smoke too).
set -eu
pkgs="build-essential cmake git pkg-config dpkg-dev openmpi-bin libopenmpi-dev
      libfftw3-dev libpng-dev libjpeg-dev zlib1g-dev python3 ccache gnuplot-nox"
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
