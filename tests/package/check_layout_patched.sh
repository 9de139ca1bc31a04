#!/bin/bash
# ctest package.layout: the build-time layout check must stop the build when the headers differ
# from the installed library. A copy of YADE's headers (links, with core/State.hpp a real file)
# gets one member inserted before State::vel; configuring the project on that copy and building
# the check must fail, naming State.
set -u
src=$1 build=$2
yade_src=$(sed -n 's/^YADE_SOURCE_DIR:PATH=//p' "$build/CMakeCache.txt")
[ -f "$yade_src/core/State.hpp" ] || { echo "FAIL no YADE source in $build/CMakeCache.txt"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -rs "$yade_src" "$tmp/yade"
rm "$tmp/yade/core/State.hpp"
sed 's|^\t\t((Vector3r,vel,Vector3r::Zero(),,"Current linear velocity."))|\t\t((Real,layoutTestPad,0,,"inserted by the test"))\n&|' "$yade_src/core/State.hpp" > "$tmp/yade/core/State.hpp"
if cmp -s "$yade_src/core/State.hpp" "$tmp/yade/core/State.hpp"; then echo "FAIL the patch did not apply to State.hpp"; exit 1; fi
echo "patched a copy of core/State.hpp: a Real member before vel"
cmake -S "$src" -B "$tmp/build" -DYADE_SOURCE_DIR="$tmp/yade" > "$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log"; echo "FAIL configure"; exit 1; }
if cmake --build "$tmp/build" --target layout_check > "$tmp/build.log" 2>&1; then
    echo "FAIL the layout check passed with a patched header"; exit 1
fi
line=$(grep "layout check FAILED" "$tmp/build.log")
echo "$line"
case "$line" in
    *State*) echo "ok   the build stopped at the layout check, naming State" ;;
    *) tail -20 "$tmp/build.log"; echo "FAIL the build did not stop at the layout check naming State"; exit 1 ;;
esac
