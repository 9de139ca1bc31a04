"""The ensemble's committed campaign (issue #59; plain Python): from a working folder (``results/ensemble``)
copy what the report and the prediction read into a campaign folder, leaving out the blocks' scenes,
checkpoints' scenes and logs. Per block: every finished collision (ensemble/*.json), the finished cycle
and pull runs (energy-cycles-*, rate-cycles-*, pull-* as CSV and JSON; a run still going has no JSON
beside its CSV), a pull not finished as its last save's description (pull-*.checkpoint.yade.gz.json: its
rows and events, which ``python3 -m mesostudies.agglomerate.tension`` reads), and the descriptions of the
block and of its pair (*.yade.gz.json); every block's pair itself too (agglomerates.yade.gz: ``predict``
takes the meso pair's radii and masses from block 1's, and a campaign copied to a new machine goes on
without sintering its blocks again, an hour each)::

    python3 -m mesostudies.agglomerate.collect results/ensemble campaigns/agglomerate-ensemble
    yade -n -x studies/scripts/agglomerate.py predict --out campaigns/agglomerate-ensemble

Returns (and prints) the number of files copied.
"""
import os
import shutil
import sys

RUNS = ("energy-cycles-", "rate-cycles-", "pull-")
DESCRIPTIONS = ("block.yade.gz.json", "agglomerates.yade.gz.json")


def _wanted(folder, name):
    """Whether ``name`` in block folder ``folder`` belongs to the campaign."""
    if name in DESCRIPTIONS or name == "agglomerates.yade.gz":
        return True
    if name.startswith("pull-") and name.endswith(".checkpoint.yade.gz.json"):
        stem = name[:-len(".checkpoint.yade.gz.json")]  # a pull not finished: its last save's rows and events
        return not os.path.exists(os.path.join(folder, stem + ".json"))
    if not name.startswith(RUNS) or ".checkpoint" in name:
        return False
    stem, ext = os.path.splitext(name)
    return ext in (".csv", ".json") and all(os.path.exists(os.path.join(folder, stem + e)) for e in (".csv", ".json"))


def collect(src, dst):
    n = 0
    for block in sorted(b for b in os.listdir(src) if b.startswith("block-s") and os.path.isdir(os.path.join(src, b))):
        here = os.path.join(src, block)
        for name in sorted(os.listdir(here)):
            if os.path.isfile(os.path.join(here, name)) and _wanted(here, name):
                os.makedirs(os.path.join(dst, block), exist_ok=True)
                shutil.copy2(os.path.join(here, name), os.path.join(dst, block, name))
                n += 1
        runs = os.path.join(here, "ensemble")
        if os.path.isdir(runs):
            os.makedirs(os.path.join(dst, block, "ensemble"), exist_ok=True)
            for name in sorted(f for f in os.listdir(runs) if f.endswith(".json")):
                shutil.copy2(os.path.join(runs, name), os.path.join(dst, block, "ensemble", name))
                n += 1
    return n


def main(argv):
    if len(argv) != 2:
        raise SystemExit("usage: python3 -m mesostudies.agglomerate.collect SRC DST")
    if not os.path.isdir(argv[0]):
        raise SystemExit(f"SRC = {argv[0]!r} is not a folder")
    print(f"{collect(*argv)} files copied to {argv[1]}")


if __name__ == "__main__":
    main(sys.argv[1:])
