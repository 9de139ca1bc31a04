"""every fenced `python` block of `README.md` and `docs/**/*.md` runs alone in YADE (the build-tree
launcher, -j1, a fresh directory); where the docs show the output (a `text` block after it), the
printed lines must be those, numbers to 1e-9. `<!-- snippet: skip REASON -->` before a block leaves
it out with the reason printed (one today: the yade.mpy template of `docs/mpi.md`, whose runnable
form is `tests/mpi/split.py`); `<!-- snippet: copy SRC DEST -->` gives it a data file.

A block is followed by a ```text block (after a paragraph starting with "prints", if any) when
the docs show its output: the printed lines must be
those (numbers compared to 1e-9 relative, so that a last-digit difference of a libm does not fail
it, while any physics change does). Directives in an HTML comment on the line before a block:
  <!-- snippet: skip REASON -->          not run (a template, or it needs MPI); the reason is printed
  <!-- snippet: copy SRC DEST -->        copies SRC (relative to the repository) into the block's
                                         directory as DEST before it runs
    python3 tests/docs/run_snippets.py build/yade-meso [FILE.md ...]"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


def blocks(path):
    """(line number, code, expected output or None, directives) of each python block."""
    lines = open(path, encoding="utf-8").read().split("\n")
    out, i = [], 0
    while i < len(lines):
        if lines[i].strip() != "```python":
            i += 1
            continue
        start, directives = i + 1, []
        k = i - 1
        while k >= 0 and lines[k].strip().startswith("<!-- snippet:"):
            directives.append(lines[k].strip()[len("<!-- snippet:"):-len("-->")].strip())
            k -= 1
        j = start
        while lines[j].strip() != "```":
            j += 1
        code = "\n".join(lines[start:j]) + "\n"
        expected, k = None, j + 1
        while k < len(lines) and not lines[k].strip():
            k += 1
        if k < len(lines) and lines[k].startswith("prints"):  # a sentence introducing the output
            while k < len(lines) and lines[k].strip():
                k += 1
            while k < len(lines) and not lines[k].strip():
                k += 1
        if k < len(lines) and lines[k].strip() == "```text":
            e = k + 1
            while lines[e].strip() != "```":
                e += 1
            expected = lines[k + 1:e]
            j = e
        out.append((start, code, expected, directives))
        i = j + 1
    return out


def same_line(got, want):
    """Equal text with the numbers equal to 1e-9 relative."""
    if NUMBER.sub("#", got).rstrip() != NUMBER.sub("#", want).rstrip():
        return False
    for a, b in zip(NUMBER.findall(got), NUMBER.findall(want)):
        x, y = float(a), float(b)
        if abs(x - y) > 1e-9 * max(abs(x), abs(y)):
            return False
    return True


def run(yade, path, line, code, expected, directives):
    name = f"{os.path.relpath(path, ROOT)}:{line}"
    for d in directives:
        if d.startswith("skip"):
            print(f"SKIP {name}: {d[4:].strip()}")
            return "skip"
    work = tempfile.mkdtemp(prefix="snippet-")
    for d in directives:
        if d.startswith("copy"):
            _, src, dest = d.split()
            shutil.copy(os.path.join(ROOT, src), os.path.join(work, dest))
    with open(os.path.join(work, "snippet.py"), "w") as f:
        f.write(code)
    r = subprocess.run([yade, "-j1", "-n", "-x", "snippet.py"], cwd=work, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        print(f"FAIL {name}: exit {r.returncode}\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}")
        return "fail"
    if expected is not None:
        got = [ln for ln in r.stdout.split("\n") if ln.strip()]
        want = [ln for ln in expected if ln.strip()]
        # YADE prints its banner and messages too: the block's lines must appear in order at the end.
        tail = got[-len(want):] if want else []
        if len(tail) != len(want) or not all(same_line(g, w) for g, w in zip(tail, want)):
            print(f"FAIL {name}: printed\n  " + "\n  ".join(tail) + "\nwhere the docs show\n  " + "\n  ".join(want))
            return "fail"
    print(f"ok   {name}" + (f" ({len(expected)} lines of output checked)" if expected else " (ran)"))
    shutil.rmtree(work, ignore_errors=True)
    return "ok"


def main():
    yade = os.path.abspath(sys.argv[1])
    files = sys.argv[2:] or [os.path.join(ROOT, "README.md")] + sorted(
        glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))
    counts = {"ok": 0, "skip": 0, "fail": 0}
    for path in files:
        for line, code, expected, directives in blocks(path):
            counts[run(yade, path, line, code, expected, directives)] += 1
    print(f"snippets: {counts['ok']} passed, {counts['fail']} failed, {counts['skip']} skipped")
    if counts["ok"] + counts["fail"] == 0:
        sys.exit("no snippet ran")
    sys.exit(1 if counts["fail"] else 0)


if __name__ == "__main__":
    main()
