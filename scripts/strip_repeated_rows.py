"""Removes the repeated first data row from the tablet campaign's committed CSVs (issue #50, item 5).

Why it exists: until #50 a uni-axial test (mesostudies.tablet.uniaxial.Test) recorded its start
twice, once explicitly and once by its recorder in the next step at the same iteration; the
writer now keeps one row per iteration. This one-off script brings the committed files in line.

What it does: in every CSV whose header starts with ``iter,`` (under the folders or files given),
it removes a data row identical to the row before it (every field the same text, so the same
iter). Every other byte stays as it was: the header, the number formatting, the line endings. A
file where two consecutive rows have the same iter but different values is refused: reported and
left unchanged (exit status 1). Per file it reports how many rows it removed.

    python3 scripts/strip_repeated_rows.py [--dry-run] PATH...
"""
import argparse
import os
import sys


def strip(data):
    """(new bytes, rows removed, refusals) for a CSV's bytes; refusals lists (line number, iter)
    of consecutive rows with the same iter and different values (then nothing is removed)."""
    lines = data.splitlines(keepends=True)
    keep, removed, refused = lines[:1], 0, []
    prev = None
    for n, line in enumerate(lines[1:], start=2):
        fields = line.rstrip(b"\r\n").split(b",")
        if prev is not None and fields[0] == prev[0]:
            if fields == prev:
                removed += 1
                if not line.endswith((b"\n", b"\r")) and keep:  # the last line had no line end: nor has the new last
                    keep[-1] = keep[-1].rstrip(b"\r\n")
                continue
            refused.append((n, fields[0].decode(errors="replace")))
        keep.append(line)
        prev = fields
    if refused:
        return data, 0, refused
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
            where = ", ".join(f"line {n} (iter {it})" for n, it in refused[:3]) + (" ..." if len(refused) > 3 else "")
            print(f"{path}: refused, left unchanged: the same iter as the row before with other values at {where}")
            continue
        if removed:
            changed += 1
            rows += removed
            if not args.dry_run:
                tmp = path + ".tmp-strip"
                with open(tmp, "wb") as f:
                    f.write(new)
                os.chmod(tmp, os.stat(path).st_mode & 0o7777)
                os.replace(tmp, path)
        print(f"{path}: {removed} row{'s' if removed != 1 else ''} removed")
    print(f"{'would change' if args.dry_run else 'changed'} {changed} files, {rows} rows removed; {refusals} refused")
    return 1 if refusals else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
