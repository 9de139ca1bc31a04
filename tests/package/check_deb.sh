#!/usr/bin/env bash
# ctest: CPack's DEB generator makes the package the README installs (built into a temporary
# directory from this build tree): the plugin stripped in YADE's library directory, the Python
# package on YADE's interpreter's path, scripts and examples under /usr/share/yade-meso, and
# Depends on the exact libyade/yade version the plugin was built and checked against.
#   bash tests/package/check_deb.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: check_deb.sh BUILD_DIR}" && pwd)
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
(cd "$out" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out" > cpack.log 2>&1) || { cat "$out/cpack.log"; exit 1; }
deb=$(ls "$out"/yade-meso_*_amd64.deb)
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
files=$(dpkg-deb -c "$deb" | awk '{print $6}')
libdir=$(dirname "$(dpkg -L libyade | grep '/libyade\.so$' | head -n1)")
pyver=$(/usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')
check "plugin in YADE's library directory ($libdir)" "grep -qx '.$libdir/libyade_meso.so' <<< \"\$files\""
check "Python package on /usr/bin/python3's path" "grep -qx './usr/lib/python$pyver/dist-packages/mesocontact/theory.py' <<< \"\$files\""
check "scripts and examples under /usr/share/yade-meso" "grep -q '^./usr/share/yade-meso/scripts/calibrate.py$' <<< \"\$files\" && grep -q '^./usr/share/yade-meso/examples/deposition.py$' <<< \"\$files\""
check "no study, campaign or study script: $(grep -c . <<< "$files") entries" "! grep -q 'mesostudies\|campaigns\|/studies/scripts/figure.py\|/scripts/tablet_\|tablet-campaign.table' <<< \"\$files\""
check "the README's installed yade-batch files" "grep -q '^./usr/share/yade-meso/examples/pair-batch.table$' <<< \"\$files\" && grep -q '^./usr/share/yade-meso/scripts/pair_batch.py$' <<< \"\$files\""
check "no __pycache__ and nothing under /usr/local" "! grep -q '__pycache__\|^./usr/local' <<< \"\$files\""
tmp=$(mktemp -d); dpkg-deb -x "$deb" "$tmp"
size=$(stat -c %s "$tmp$libdir/libyade_meso.so")
docs=$(du -sb "$tmp/usr/share/doc/yade-meso" | cut -f1)
check "the library's docs only, no study page or picture: $docs bytes (<= 1 MB)" "[ $docs -le 1000000 ] && ! grep -q 'doc/yade-meso/docs/\(tablet\|figures\|agglomerate\)' <<< \"\$files\""
debsize=$(stat -c %s "$deb")
check "the package itself: $debsize bytes (<= 3 MB)" "[ $debsize -le 3000000 ]"
check "plugin stripped: $size bytes, no debug sections" "[ $size -lt 15000000 ] && ! readelf -S '$tmp$libdir/libyade_meso.so' | grep -q debug_info"
rm -rf "$tmp"
ver=$(dpkg-query -W -f='${Version}' libyade)
dep=$(dpkg-deb -f "$deb" Depends)
check "Depends on libyade (= $ver) and yade (= $ver): $dep" "grep -q 'libyade (= $ver)' <<< \"\$dep\" && grep -q 'yade (= $ver)' <<< \"\$dep\""
exit $fail
