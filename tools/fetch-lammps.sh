#!/usr/bin/env bash
# Fetch a LAMMPS source tree from Debian's source packages into a cache
# outside the work tree, verify the upstream tarball's checksum, unpack it
# once and print the source dir.
#   fetch-lammps.sh <cache-dir> [2026|2021]
#   2026 (default): LAMMPS 4 Jul 2026, Debian unstable (sid) lammps 20260704+dfsg
#   2021:           LAMMPS 29 Sep 2021 update 2, Debian bookworm
# apt runs with a private sources list and state under <cache-dir>/apt: the
# machine's apt configuration is neither read for sources nor changed. When
# 2026 cannot be fetched, the 2021 tree is used and a message says so.
set -eu
cache=$1
release=${2:-2026}

fetch() {  # <suite> <version> <orig tarball> <sha256> <tree dir>
  local suite=$1 version=$2 orig=$3 sha256=$4 src=$5
  if [ -f "$src/.pdext-ok" ]; then return 0; fi
  mkdir -p "$cache/dl"
  if [ ! -f "$cache/dl/$orig" ]; then
    local apt="$cache/apt/$suite"
    mkdir -p "$apt/sources" "$apt/lists/partial" "$apt/cache/archives/partial"
    cat > "$apt/sources/debian.sources" <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: $suite
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
    local opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$apt/sources"
                -o "Dir::State::Lists=$apt/lists" -o "Dir::Cache=$apt/cache"
                -o "APT::Sandbox::User=$(id -un)")
    apt-get "${opts[@]}" update -qq >&2 || return 1
    # Only the upstream tarball is used: apt's verdict on the Debian parts
    # (.dsc, patches) does not matter, the tarball's checksum below does. A
    # later Debian revision of the same upstream release ships the same one.
    (cd "$cache/dl" && apt-get "${opts[@]}" source --download-only "lammps=$version" >&2) || true
    [ -f "$cache/dl/$orig" ] \
      || (cd "$cache/dl" && apt-get "${opts[@]}" source --download-only lammps >&2) || true
    [ -f "$cache/dl/$orig" ] || { echo "fetch-lammps: $orig not found in Debian $suite" >&2; return 1; }
  fi
  echo "$sha256  $cache/dl/$orig" | sha256sum -c --quiet - >&2 \
    || { echo "fetch-lammps: checksum mismatch for $cache/dl/$orig" >&2; return 1; }
  rm -rf "$src.tmp" && mkdir -p "$src.tmp"
  tar -xf "$cache/dl/$orig" -C "$src.tmp" || return 1
  # one top folder (the 2021 tarball) or the tree itself (the 2026 one)
  local top="$src.tmp"
  [ -d "$top/src" ] || top=$(find "$src.tmp" -mindepth 1 -maxdepth 1 -type d)
  [ -d "$top/src" ] && [ -d "$top/cmake" ] \
    || { echo "fetch-lammps: $orig holds no LAMMPS source tree (src/, cmake/)" >&2; return 1; }
  rm -rf "$src" && mv "$top" "$src" && rm -rf "$src.tmp"
  touch "$src/.pdext-ok"
}

fetch_2021() {
  fetch bookworm "20220106.git7586adbb6a+ds1-2" "lammps_20220106.git7586adbb6a+ds1.orig.tar.xz" \
    65146c615ad24d8b8bc64f4e05e86226a7f1fdb45c0b5ea9416562b9f3863082 "$cache/lammps-20220106"
  echo "$cache/lammps-20220106"
}

case $release in
  2026)
    if fetch sid "20260704+dfsg-2" "lammps_20260704+dfsg.orig.tar.gz" \
         cddbc45a047416bd48a4a0b87f24a5b61b3446982b74d18cafe619c22b17eb62 "$cache/lammps-20260704"; then
      echo "$cache/lammps-20260704"
    else
      echo "fetch-lammps: LAMMPS 4 Jul 2026 (Debian unstable's source package lammps 20260704+dfsg-2)" \
           "could not be fetched or verified; building against LAMMPS 29 Sep 2021 (Debian bookworm) instead" >&2
      fetch_2021
    fi ;;
  2021) fetch_2021 ;;
  *) echo "fetch-lammps: unknown release '$release' (expected 2026 or 2021)" >&2; exit 2 ;;
esac
