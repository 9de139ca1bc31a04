"""What the YADE test scripts share (ctest puts this directory on PYTHONPATH): one line per
check, "ok   ..." or "FAIL ...", and an end that lists the failures and sets the exit code."""
import sys

failures = []


def check(ok, label, detail=""):
    """Prints the check's line and remembers a failure; returns ok."""
    print(("ok   " if ok else "FAIL ") + label + (f": {detail}" if detail else ""), flush=True)
    if not ok:
        failures.append(label)
    return ok


def finish():
    """Ends the script: exit code 1 and the list of failed checks, or "all passed"."""
    if failures:
        print(f"{len(failures)} FAILED: {failures}", flush=True)
        sys.exit(1)
    print("all passed", flush=True)
