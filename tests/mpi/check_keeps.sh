#!/usr/bin/env bash
# ctest mpi.split, mpi.realloc, mpi.tablet, mpi.tablet_realloc: the law under `yade.mpy`
# (`docs/mpi.md`), a master and two workers under `mpiexec`, oversubscribed: a bed saved serially
# (`split.py`) and the quick tablet (`tablet.py`) give every contact bitwise equal to serial right
# after the split, and the run after it (and the contacts merged back on the master) equal to serial
# up to summation order (bounds and measurements in the scripts' headers). The `_realloc` variants
# let mpy move bodies between the workers (its own filter on an uneven bed; a swinging cut in the
# tablet, 612 moves). Each check runs again with `--lose`, without what it tests (`keep_contacts`;
# for the `_realloc` variants the contacts sent with moved bodies), and must fail.
#
# A check script of this directory (split.py, tablet.py) serially,
# then on a master and two workers. The run with mesocontact.mpi.keep_contacts must pass (it
# equals the serial run: bitwise at the split, to summation order after it); the same run with
# --lose (without what is under test: keep_contacts, what mpy alone does) must fail, so the check
# can see lost history. Further arguments go to every run (--realloc: mpy moves bodies).
#   check_keeps.sh LAUNCHER SCRIPT [--prepare] [ARGS...]
set -euo pipefail
launcher=$1
script=$2
shift 2
prepare=""
[[ "${1:-}" == --prepare ]] && { prepare=1; shift; }
args=("$@")
here=$(cd "$(dirname "$0")" && pwd)
name="mpi.$(basename "$script" .py)${args[*]:+ ${args[*]}}"
dir=$(mktemp -d "/tmp/mpi.$(basename "$script" .py)-XXXXXX")
trap 'rm -rf "$dir"' EXIT
mpi=(timeout -s KILL 400 mpiexec --allow-run-as-root --oversubscribe -n 3)
report="start:\|end:\|merged:\|wall forces\|after the split\|cycle (\|reallocation:"
serially() {
  "$launcher" -j1 -n -x "$here/$script" "$1" "$dir" "${args[@]}" > "$dir/$1.log" 2>&1 || { tail -20 "$dir/$1.log"; exit 1; }
}
[[ -n "$prepare" ]] && serially prepare
serially serial
if ! "${mpi[@]}" "$launcher" -j1 -n -x "$here/$script" mpi "$dir" "${args[@]}" > "$dir/mpi.log" 2>&1; then
  grep -v "^XMLRPC\|TCP python\|Welcome\|Using python\|Running script" "$dir/mpi.log" | tail -40
  echo "$name: FAILED: the run with keep_contacts does not equal the serial run"; exit 1
fi
grep "$report" "$dir/mpi.log"
if "${mpi[@]}" "$launcher" -j1 -n -x "$here/$script" mpi "$dir" "${args[@]}" --lose > "$dir/lose.log" 2>&1; then
  echo "$name: FAILED: with --lose the run passed too (the check cannot see lost history)"; exit 1
fi
grep "$report" "$dir/lose.log" | sed 's/^/--lose: /'
echo "$name: ok"
