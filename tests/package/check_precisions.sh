#!/bin/bash
# ctest package.precisions: what runs with which YADE precision. The plugin is built for the double
# library only (README, "Two commands"); every other precision Debian installs starts without it
# (MesoMat absent, no crash), and the Debian package puts the plugin only into double's library
# directory.
set -u
build=$1
script=$(mktemp --suffix=.py)
trap 'rm -f "$script"' EXIT
cat > "$script" <<'PY'
import yade.wrapper, yade.config
print("precision", yade.config.highPrecisionBits if hasattr(yade.config, "highPrecisionBits") else "?",
      "MesoMat" if hasattr(yade.wrapper, "MesoMat") else "no MesoMat")
PY
fail=0
out=$("$build/yade-meso" -j1 -n -x "$script" 2>&1 | grep "^precision")
echo "yade (double, build tree): $out"
case "$out" in *"no MesoMat"*|"") echo "FAIL the double build does not load MesoMat"; fail=1 ;; esac
for exe in /usr/bin/yade-longdouble /usr/bin/yade-float128 /usr/bin/yade-mpfr150; do
    [ -x "$exe" ] || continue
    out=$("$exe" -j1 -n -x "$script" 2>&1 | grep "^precision")
    echo "$(basename "$exe"): $out"
    case "$out" in *"no MesoMat"*) ;; *) echo "FAIL $(basename "$exe") did not start cleanly without the plugin"; fail=1 ;; esac
done
libdir=$(sed -n 's/^YADE_LIBDIR:PATH=//p' "$build/CMakeCache.txt")
case "$libdir" in */yade|*/yade-double) echo "ok   the package installs into $libdir (double)";; *) echo "FAIL plugin directory $libdir is not double's"; fail=1;; esac
[ $fail = 0 ] && echo "all passed"
exit $fail
