"""Removes the repeated start row from the tablet campaign's committed CSVs (issue #50, item 5).

Why it exists: until #50 a uni-axial test (mesostudies.tablet.uniaxial.Test) recorded its start
twice: once explicitly, then by its recorder in the next step at the same iteration (the force
after that step, the branch fractions after it). The writer now records each iteration once and
keeps the first of those rows. This one-off script makes the committed files what a rerun writes.

What it does: in every CSV whose header starts with ``iter,`` (under the folders or files given),
a data row whose iter is the previous row's is removed, whether or not its values are the same:
the later row, the one the fixed writer no longer writes. Every other byte stays as it was: the
header, the number formatting, the line endings. Such a repeat is expected only at the start of a
test, which is the start of the file (each CSV holds one test): the first two data rows, at the
same iter and the same Dx (the walls have not moved yet). A file with anything else (a repeated
iter further down, three rows at one iter, a different Dx) is refused: reported and left
unchanged (exit status 1). Per file it reports which rows it removed.

    python3 studies/scripts/strip_repeated_rows.py [--dry-run] PATH...
"""
import argparse
import os
import sys


def strip(data):
    """(new bytes, removed, refusals) for a CSV's bytes: removed lists (line number, iter) of the
    rows taken out, refusals (line number, iter, why) of repeats other than the start's (then
    nothing is removed)."""
    lines = data.splitlines(keepends=True)
    keep, removed, refused = lines[:1], [], []
    prev, run = None, 1  # the previous data row's fields, how many rows its iter has had so far
    for n, line in enumerate(lines[1:], start=2):
        fields = line.rstrip(b"\r\n").split(b",")
        if prev is not None and fields[0] == prev[0]:
            run += 1
            it = fields[0].decode(errors="replace")
            if n != 3:
                refused.append((n, it, "not at the start of the rows"))
            elif fields[1:2] != prev[1:2]:
                refused.append((n, it, "Dx differs from the row before"))
            if run > 2:
                refused.append((n, it, f"{run} rows at one iter"))
            removed.append((n, it))
            if not line.endswith((b"\n", b"\r")):  # the last line had no line end: nor has the new last
                keep[-1] = keep[-1].rstrip(b"\r\n")
            continue
        keep.append(line)
        prev, run = fields, 1
    if refused:
        return data, [], refused
    return b"".join(keep), removed, []


def csv_files(paths):
    for p in paths:
        if os.path.isdir(p):
            for top, dirs, names in os.walk(p):
                dirs.sort()
                yield from (os.path.join(top, n) for n in sorted(names) if n.endswith(".csv"))
        else:
            yield p


def main(argv):
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("paths", nargs="+", help="CSV files or folders (searched for *.csv)")
    a.add_argument("--dry-run", action="store_true", help="report, write nothing")
    args = a.parse_args(argv)
    changed = rows = refusals = 0
    for path in csv_files(args.paths):
        with open(path, "rb") as f:
            data = f.read()
        if not data.startswith(b"iter,"):
            continue
        new, removed, refused = strip(data)
        if refused:
            refusals += 1
            where = "; ".join(f"line {n} (iter {it}): {why}" for n, it, why in refused[:3])
            print(f"{path}: refused, left unchanged: {where}{' ...' if len(refused) > 3 else ''}")
            continue
        if removed:
            changed += 1
            rows += len(removed)
            if not args.dry_run:
                tmp = path + ".tmp-strip"
                with open(tmp, "wb") as f:
                    f.write(new)
                os.chmod(tmp, os.stat(path).st_mode & 0o7777)
                os.replace(tmp, path)
        what = ", ".join(f"line {n} (iter {it})" for n, it in removed)
        print(f"{path}: {len(removed)} row{'s' if len(removed) != 1 else ''} removed{': ' + what if what else ''}")
    print(f"{'would change' if args.dry_run else 'changed'} {changed} files, {rows} rows removed; {refusals} refused")
    return 1 if refusals else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
