"""What the YADE test scripts share (ctest puts this directory on PYTHONPATH): one line per
check, "ok   ..." or "FAIL ...", and an end that lists the failures and sets the exit code."""
import os
import sys
import tempfile

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


class Stderr:
    """What the process writes to file descriptor 2 (the plugin's C++ warnings) while inside:
    ``with Stderr() as err: ...`` then ``err.text`` (also echoed to stderr for the test's log)."""
    def __enter__(self):
        sys.stderr.flush()
        self.file = tempfile.TemporaryFile(mode="w+")
        self.saved = os.dup(2)
        os.dup2(self.file.fileno(), 2)
        return self

    def __exit__(self, *exc):
        sys.stderr.flush()
        os.dup2(self.saved, 2)
        os.close(self.saved)
        self.file.seek(0)
        self.text = self.file.read()
        self.file.close()
        sys.stderr.write(self.text)


def die_start(path):
    """Loads the released sample at ``path`` and makes the die's start (bulk.uniaxial.make_confined):
    returns (the walls' positions before, {name: id} of the four lateral walls, a uniaxial.Test)."""
    from yade import O
    from mesocontact.bulk import sample, uniaxial
    O.reset()
    O.load(path)
    before = {k: tuple(O.bodies[i].state.pos) for k, i in sample.wall_ids().items()}
    uniaxial.make_confined(progress=False)
    lateral = {k: i for k, i in sample.wall_ids().items() if k not in ("left", "right")}
    return before, lateral, uniaxial.Test(progress=False)


class FirstSaveKept:
    """Within the block, ``cls.save`` (a checkpointing class's: Pair, Test) also records each save's
    step in ``self.steps`` and copies the first save's two files to ``kept`` (a .yade.gz path): the
    state a new process would have found had the first one died there."""

    def __init__(self, cls, kept):
        self.cls, self.kept, self.steps = cls, kept, []

    def __enter__(self):
        import shutil
        from yade import O
        save = self.save = self.cls.save

        def save_and_keep(obj, path):
            save(obj, path)
            self.steps.append(O.iter)
            if len(self.steps) == 1:
                shutil.copy(path, self.kept)
                shutil.copy(path + ".json", self.kept + ".json")
        self.cls.save = save_and_keep
        return self

    def __exit__(self, *exc):
        self.cls.save = self.save
