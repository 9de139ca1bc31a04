#!/usr/bin/env bash
# ctest mpi.tablet: tests/mpi/tablet.py on the quick tablet, a master (the loading walls) and two
# workers. With mesocontact.mpi.keep_contacts every contact equals the serial one bitwise after the
# split and the force rows of a tension cycle agree with serial; without it the check must fail.
set -euo pipefail
launcher=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d /tmp/mpi-tablet-XXXXXX)
trap 'rm -rf "$dir"' EXIT
mpi=(timeout -s KILL 400 mpiexec --allow-run-as-root --oversubscribe -n 3)
"$launcher" -j1 -n -x "$here/tablet.py" serial "$dir" > "$dir/serial.log" 2>&1 || { tail -20 "$dir/serial.log"; exit 1; }
if ! "${mpi[@]}" "$launcher" -j1 -n -x "$here/tablet.py" mpi "$dir" > "$dir/mpi.log" 2>&1; then
  grep -v "^XMLRPC\|TCP python\|Welcome\|Using python\|Running script" "$dir/mpi.log" | tail -40
  echo "mpi.tablet: FAILED: the tablet under mpy does not equal the serial run"; exit 1
fi
grep "after the split\|cycle (" "$dir/mpi.log"
if "${mpi[@]}" "$launcher" -j1 -n -x "$here/tablet.py" mpi "$dir" --lose > "$dir/lose.log" 2>&1; then
  echo "mpi.tablet: FAILED: without keep_contacts the run passed too (the check cannot see lost history)"; exit 1
fi
grep "after the split\|cycle (" "$dir/lose.log" | sed 's/^/without keep_contacts: /'
echo "mpi.tablet: ok"
