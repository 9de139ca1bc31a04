"""Result files that are whole or absent (plain Python).

A result (one run's CSV and JSON; a figure's JSON, PNG and the runs it plots) is a *bundle*: a
directory whose files are written under a hidden temporary name and committed by one rename
(or, over an older bundle, one atomic exchange of the two directories), with a MANIFEST.json of
their SHA-256 sums. A job stopped at any moment (SIGTERM, SIGKILL, a
crash) leaves either the previous bundle or the new one under the result's name, never a mix;
its unfinished work is a hidden ``.<name>.tmp-<pid>-...`` directory, which ``sweep`` removes once
that process is gone. ``problems`` lists whatever does not satisfy this (for tests and for the
kill trials of studies/scripts/campaign_kill_trials.py).
"""
import ctypes
import hashlib
import json
import os
import shutil
import signal
import uuid

MANIFEST = "MANIFEST.json"
_OPEN = set()  # temporary directories of this process, removed on SIGTERM


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def read_csv(path):
    """The rows of a CSV of numbers with one header line, each a tuple of floats."""
    with open(path) as f:
        return [tuple(float(x) for x in line.split(",")) for line in f.read().split("\n")[1:] if line]


def write_atomic(path, text):
    """A single file under a temporary name, then renamed: readers see the old or the new one."""
    tmp = f"{path}.tmp-{os.getpid()}-{uuid.uuid4().hex[:8]}"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def savefig_atomic(fig, path, **kw):
    """A matplotlib figure saved under a temporary name (same extension), then renamed."""
    root, ext = os.path.splitext(path)
    tmp = f"{root}.tmp-{os.getpid()}-{uuid.uuid4().hex[:8]}{ext}"
    fig.savefig(tmp, **kw)
    os.replace(tmp, path)


_LIBC = ctypes.CDLL(None, use_errno=True)
_RENAME_EXCHANGE = 2  # linux/fs.h


def _exchange(a, b):
    """Swaps two existing paths atomically (Linux renameat2 with RENAME_EXCHANGE)."""
    if _LIBC.renameat2(-100, os.fsencode(a), -100, os.fsencode(b), _RENAME_EXCHANGE) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"renameat2({a}, {b}, RENAME_EXCHANGE): {os.strerror(err)}")


def _on_sigterm(signum, frame):
    for d in list(_OPEN):
        shutil.rmtree(d, ignore_errors=True)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    os.kill(os.getpid(), signal.SIGTERM)


class Bundle:
    """Files of one result, written into a temporary directory and committed as ``final``.

        with Bundle(os.path.join(out, "fig16")) as b:
            b.write_json("fig16.json", summary); fig.savefig(b.path("fig16.png"))

    Leaving the block by an exception discards everything; leaving it normally commits."""

    def __init__(self, final):
        self.final = os.path.abspath(final)
        parent, name = os.path.split(self.final)
        os.makedirs(parent, exist_ok=True)
        self.tmp = os.path.join(parent, f".{name}.tmp-{os.getpid()}-{uuid.uuid4().hex[:8]}")
        os.makedirs(self.tmp)
        _OPEN.add(self.tmp)
        if signal.getsignal(signal.SIGTERM) in (signal.SIG_DFL, None):
            try:
                signal.signal(signal.SIGTERM, _on_sigterm)
            except ValueError:  # not the main thread: the hidden directory stays for sweep()
                pass

    def path(self, name):
        return os.path.join(self.tmp, name)

    def write_text(self, name, text):
        with open(self.path(name), "w") as f:
            f.write(text)

    def write_json(self, name, obj):
        self.write_text(name, json.dumps(obj, indent=1))

    def copy_from(self, bundle_dir, only=None):
        """Copies the files of a committed bundle (all, or the names in ``only``) into this one."""
        for f in sorted(os.listdir(bundle_dir)):
            if f != MANIFEST and (only is None or f in only):
                shutil.copy(os.path.join(bundle_dir, f), self.path(f))

    def commit(self):
        files = sorted(f for f in os.listdir(self.tmp) if f != MANIFEST)
        with open(self.path(MANIFEST), "w") as f:
            json.dump({name: sha256(self.path(name)) for name in files}, f, indent=1)
        last = None
        for _ in range(5):  # another job may commit the same result at the same time
            try:
                if os.path.exists(self.final):
                    # One atomic swap: the name holds the old bundle or the new one at every
                    # instant, and the old one lands in our temporary directory, which a signal
                    # handler or sweep() may remove at any moment.
                    _exchange(self.tmp, self.final)
                else:
                    os.rename(self.tmp, self.final)
            except OSError as e:  # another job committed or swapped in between: try again
                last = e
                continue
            shutil.rmtree(self.tmp, ignore_errors=True)
            _OPEN.discard(self.tmp)
            return self.final
        raise RuntimeError(f"could not commit {self.final}: {last}")

    def discard(self):
        shutil.rmtree(self.tmp, ignore_errors=True)
        _OPEN.discard(self.tmp)

    def __enter__(self):
        return self

    def __exit__(self, kind, value, tb):
        if kind is None:
            self.commit()
        else:
            self.discard()
        return False


def complete(bundle_dir):
    """True if the directory is a committed bundle whose files are exactly those of its manifest."""
    try:
        with open(os.path.join(bundle_dir, MANIFEST)) as f:
            manifest = json.load(f)
    except (OSError, ValueError):
        return False
    files = sorted(f for f in os.listdir(bundle_dir) if f != MANIFEST)
    return files == sorted(manifest) and all(sha256(os.path.join(bundle_dir, f)) == h for f, h in manifest.items())


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _tmp_pid(name):
    try:
        return int(name.split(".tmp-")[1].split("-")[0])
    except (IndexError, ValueError):
        return None


def sweep(root):
    """Removes the temporary files and directories of processes that no longer run."""
    removed = []
    for parent, dirs, files in os.walk(root):
        for name in list(dirs) + files:
            pid = _tmp_pid(name)
            if pid is not None and not _alive(pid):
                p = os.path.join(parent, name)
                shutil.rmtree(p, ignore_errors=True) if os.path.isdir(p) else os.remove(p)
                removed.append(p)
                if name in dirs:
                    dirs.remove(name)
    return removed


def problems(root, bundle_parents=("runs",), ignore_running=True):
    """What does not hold in ``root``: every directory under it holding a MANIFEST (and every
    directory in ``bundle_parents``) is a complete bundle; temporary leftovers only of running
    processes. Returns a list of strings (empty: all whole)."""
    out = []
    for parent, dirs, files in os.walk(root):
        for name in dirs + files:
            pid = _tmp_pid(name)
            if pid is not None and not (ignore_running and _alive(pid)):
                out.append(f"leftover of a stopped process: {os.path.join(parent, name)}")
        dirs[:] = [d for d in dirs if _tmp_pid(d) is None]
        is_bundle = MANIFEST in files or os.path.basename(os.path.dirname(parent)) in bundle_parents \
            and os.path.basename(parent) not in bundle_parents
        if is_bundle and not complete(parent):
            out.append(f"incomplete bundle: {parent}")
    return out
