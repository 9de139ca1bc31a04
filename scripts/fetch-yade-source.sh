#!/usr/bin/env bash
# Obtains YADE's C++ headers (Debian ships none) from Debian's source package and prints the
# directory of the unpacked source tree on its last line of output.
#
# Prefers the source of the exact installed version; where the package mirror no longer serves
# it, takes the newest one it can get from the next Debian release and applies the minimal
# compatibility adjustment documented below. The mirror is read from this machine's apt
# configuration; nothing here names one.
#
# usage: fetch-yade-source.sh CACHE_DIR
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
cache=${1:?usage: fetch-yade-source.sh CACHE_DIR}
mkdir -p "$cache"
log() { echo "fetch-yade-source: $*" >&2; }

installed=$(dpkg-query -W -f='${source:Version}' libyade 2>/dev/null || true)
[ -n "$installed" ] || { log "YADE is not installed (package libyade); run scripts/install-deps.sh"; exit 1; }
libdir=$(dirname "$(dpkg -L libyade | grep '/libyade\.so$' | head -n1)")
fallback_version=${YADE_FALLBACK_SOURCE_VERSION:-2025.2.0-1}
fallback_suite=${YADE_FALLBACK_SOURCE_SUITE:-trixie}

# Already unpacked?  (one directory per version; the marker says which adjustment was made)
for v in "$installed" "$fallback_version"; do
  if [ -f "$cache/$v/.complete" ]; then echo "$cache/$v/src"; exit 0; fi
done

# The Debian archive URI this machine already uses (deb822 .sources first, then sources.list).
uri=""
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  u=$(awk 'BEGIN{IGNORECASE=1} /^URIs:/{print $2; exit}' "$f")
  if grep -qi '^Suites:.*\b'"$(. /etc/os-release; echo "$VERSION_CODENAME")"'\b' "$f" && [[ "$u" != *security* ]]; then uri=$u; break; fi
done
if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
  uri=$(awk '$1=="deb" && $0 !~ /security/ {for(i=2;i<=NF;i++) if($i ~ /^[a-z]+:\/\//){print $i; exit}}' /etc/apt/sources.list)
fi
[ -n "$uri" ] || { log "no Debian archive URI found in the apt configuration"; exit 1; }
codename=$(. /etc/os-release; echo "$VERSION_CODENAME")

# A private apt configuration for this one download (its own sources, lists and cache in a
# temporary directory): the machine's /etc/apt and /var/lib/apt stay as they were.
apt_dir=$(mktemp -d)
trap 'rm -rf "$apt_dir"' EXIT
mkdir -p "$apt_dir/sources.list.d" "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial"
cat > "$apt_dir/sources.list.d/yade-source.sources" <<SRC
Types: deb-src
URIs: $uri
Suites: $codename $fallback_suite
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
APT=(apt-get -o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$apt_dir/sources.list.d"
     -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache" -o "Debug::NoLocking=1"
     -o "APT::Sandbox::User=$(id -un)")  # a private directory: no download sandbox user needed
log "reading the source indexes of $uri ($codename, $fallback_suite) into a private apt directory"
"${APT[@]}" update -qq

try_version() {  # downloads and unpacks the .orig tarball of source version $1 into $cache/$1
  local v=$1 dl
  dl=$(mktemp -d)
  # apt-get source may fail on a missing .debian.tar.* although the .orig tarball arrived.
  (cd "$dl" && "${APT[@]}" source --download-only -qq "yade=$v" >/dev/null 2>&1) || true
  local tarball
  tarball=$(ls "$dl"/yade_*.orig.tar.* 2>/dev/null | head -n1 || true)
  if [ -z "$tarball" ]; then rm -rf "$dl"; return 1; fi
  rm -rf "$cache/$v"; mkdir -p "$cache/$v/src"
  tar -xf "$tarball" -C "$cache/$v/src" --strip-components=1
  rm -rf "$dl"
  return 0
}

if try_version "$installed"; then
  v=$installed; log "unpacked the source of the installed version $v (from $uri, $codename)"
elif try_version "$fallback_version"; then
  v=$fallback_version
  log "the source of the installed version $installed is not served; using $v (from $uri, $fallback_suite)"
else
  log "could not download YADE's source package ($installed or $fallback_version)"; exit 1
fi
src="$cache/$v/src"

# Compatibility adjustment (only for a source newer than the installed library): 2025.2's
# core/Cell.hpp binds getFluctuationVelocity to Cell::bodyFluctuationVelPy, which 2023.02a's
# libyade.so does not export; a plugin compiled with that line cannot be loaded. Drop the
# binding when the installed library lacks the symbol.
if [ "$v" != "$installed" ] && ! nm -DC --defined-only "$libdir/libyade.so" | grep -q 'Cell::bodyFluctuationVelPy'; then
  if grep -q 'bodyFluctuationVelPy' "$src/core/Cell.hpp"; then
    sed -i '/\.def("getFluctuationVelocity".*bodyFluctuationVelPy/d' "$src/core/Cell.hpp"
    grep -q '"getFluctuationVelocity".*bodyFluctuationVelPy' "$src/core/Cell.hpp" && { log "adjustment of core/Cell.hpp failed"; exit 1; }
    echo "dropped Cell.getFluctuationVelocity binding (bodyFluctuationVelPy not in installed libyade)" > "$cache/$v/ADJUSTMENTS"
    log "adjusted core/Cell.hpp: dropped the getFluctuationVelocity binding"
  fi
fi
touch "$cache/$v/.complete"
echo "$src"
