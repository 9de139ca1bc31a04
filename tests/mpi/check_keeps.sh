#!/usr/bin/env bash
# ctest mpi.split and mpi.tablet: a check script of this directory (split.py, tablet.py) serially,
# then on a master and two workers. The run with mesocontact.mpi.keep_contacts must pass (it
# equals the serial run: bitwise at the split, to summation order after it); the same run with
# --lose (without keep_contacts, what mpy alone does) must fail, so the check can see lost history.
#   check_keeps.sh LAUNCHER SCRIPT [--prepare]
set -euo pipefail
launcher=$1
script=$2
here=$(cd "$(dirname "$0")" && pwd)
name="mpi.$(basename "$script" .py)"
dir=$(mktemp -d "/tmp/$name-XXXXXX")
trap 'rm -rf "$dir"' EXIT
mpi=(timeout -s KILL 400 mpiexec --allow-run-as-root --oversubscribe -n 3)
report="start:\|end:\|wall forces\|after the split\|cycle ("
serially() {
  "$launcher" -j1 -n -x "$here/$script" "$1" "$dir" > "$dir/$1.log" 2>&1 || { tail -20 "$dir/$1.log"; exit 1; }
}
[[ "${3:-}" == --prepare ]] && serially prepare
serially serial
if ! "${mpi[@]}" "$launcher" -j1 -n -x "$here/$script" mpi "$dir" > "$dir/mpi.log" 2>&1; then
  grep -v "^XMLRPC\|TCP python\|Welcome\|Using python\|Running script" "$dir/mpi.log" | tail -40
  echo "$name: FAILED: the run with keep_contacts does not equal the serial run"; exit 1
fi
grep "$report" "$dir/mpi.log"
if "${mpi[@]}" "$launcher" -j1 -n -x "$here/$script" mpi "$dir" --lose > "$dir/lose.log" 2>&1; then
  echo "$name: FAILED: without keep_contacts the run passed too (the check cannot see lost history)"; exit 1
fi
grep "$report" "$dir/lose.log" | sed 's/^/without keep_contacts: /'
echo "$name: ok"
