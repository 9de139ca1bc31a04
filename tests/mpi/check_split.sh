#!/usr/bin/env bash
# ctest mpi.split: tests/mpi/split.py on a master and two workers. The run with
# mesocontact.mpi.keep_contacts must equal the serial run (bitwise at the split, to summation order
# after it); the same run without it must fail, so the check can see lost history.
set -euo pipefail
launcher=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d /tmp/mpi-split-XXXXXX)
trap 'rm -rf "$dir"' EXIT
mpi=(timeout -s KILL 300 mpiexec --allow-run-as-root --oversubscribe -n 3)
"$launcher" -j1 -n -x "$here/split.py" prepare "$dir" > "$dir/prepare.log" 2>&1
"$launcher" -j1 -n -x "$here/split.py" serial "$dir" > "$dir/serial.log" 2>&1
if ! "${mpi[@]}" "$launcher" -j1 -n -x "$here/split.py" mpi "$dir" > "$dir/mpi.log" 2>&1; then
  grep -v "^XMLRPC\|TCP python\|Welcome\|Using python\|Running script" "$dir/mpi.log" | tail -40
  echo "mpi.split: FAILED: the run with keep_contacts does not equal the serial run"; exit 1
fi
grep "start:\|end:\|wall forces\|mpi split" "$dir/mpi.log"
if "${mpi[@]}" "$launcher" -j1 -n -x "$here/split.py" mpi "$dir" --lose > "$dir/lose.log" 2>&1; then
  echo "mpi.split: FAILED: without keep_contacts the run passed too (the check cannot see lost history)"; exit 1
fi
grep "start:" "$dir/lose.log" | sed 's/^/without keep_contacts: /'
echo "mpi.split: ok"
