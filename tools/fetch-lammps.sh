#!/usr/bin/env bash
# Fetch Debian's LAMMPS source package (29 Sep 2021 update 2) into a cache
# outside the work tree, verify its checksum, and print the source dir.
# Usage: fetch-lammps.sh <cache-dir>
set -eu
cache=$1
version="20220106.git7586adbb6a+ds1"
orig="lammps_${version}.orig.tar.xz"
# sha256 of the upstream tarball as shipped by Debian bookworm
sha256="65146c615ad24d8b8bc64f4e05e86226a7f1fdb45c0b5ea9416562b9f3863082"
src="$cache/lammps-src"
if [ -f "$src/.pdext-ok" ]; then echo "$src"; exit 0; fi
mkdir -p "$cache/dl"
cd "$cache/dl"
if [ ! -f "$orig" ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  if ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ \
     && ! grep -qs '^deb-src' /etc/apt/sources.list; then
    echo "fetch-lammps: enabling deb-src entries" >&2
    $SUDO tee /etc/apt/sources.list.d/pdext-deb-src.sources >/dev/null <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
    $SUDO apt-get update -qq >&2
  fi
  apt-get source --download-only "lammps=${version}-2" >&2 \
    || apt-get source --download-only lammps >&2
fi
echo "$sha256  $orig" | sha256sum -c --quiet - >&2 \
  || { echo "fetch-lammps: checksum mismatch for $orig" >&2; exit 1; }
rm -rf "$src.tmp" && mkdir -p "$src.tmp"
tar -xJf "$orig" -C "$src.tmp" --strip-components=1
rm -rf "$src" && mv "$src.tmp" "$src"
touch "$src/.pdext-ok"
echo "$src"
