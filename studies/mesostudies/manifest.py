"""A campaign's manifest: what made the committed files of one folder of ``campaigns/`` and
whether they are still those files (plain Python).

    python3 -m mesostudies.manifest DIR --commit C --command "..." [--protocol JSON] [--date D] [--note TEXT]
    python3 -m mesostudies.manifest --check DIR      # exit 1 if a file differs from the manifest
    python3 -m mesostudies.manifest DIR --refresh "figures redrawn by ..."   # same runs, files changed

``CAMPAIGN.json`` records the commit whose code made the runs, the command, the preparation
(protocol), the date, the machine (processor and cores, never its name) and each file's size and
SHA-256. ``check`` lists files that are missing, changed, or not in the manifest."""
import json
import os
import sys

from mesocontact.outputs import sha256 as digest

NAME = "CAMPAIGN.json"


def files_of(folder):
    """Every file below ``folder`` but the manifest, as sorted relative paths."""
    out = []
    for top, dirs, names in os.walk(folder):
        dirs.sort()
        out += [os.path.relpath(os.path.join(top, n), folder) for n in names]
    return sorted(f for f in out if f != NAME)


def machine():
    """The processor model and core count (not the host's name)."""
    model = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            model = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), model)
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} cores"


def write(folder, commit, command, protocol=None, date=None, note=None, machine_text=None):
    """Writes ``folder``/CAMPAIGN.json for the files there now; returns the manifest."""
    if not os.path.isdir(folder):
        raise ValueError(f"folder = {folder!r} is invalid: not a directory")
    if not (isinstance(commit, str) and commit and isinstance(command, str) and command):
        raise ValueError("commit and command: non-empty strings (what made the files)")
    manifest = {"commit": commit, "command": command, "protocol": protocol, "date": date,
                "machine": machine_text or machine(), "note": note,
                "files": {f: {"bytes": os.path.getsize(os.path.join(folder, f)),
                              "sha256": digest(os.path.join(folder, f))}
                          for f in files_of(folder)}}
    with open(os.path.join(folder, NAME), "w") as f:
        json.dump(manifest, f, indent=1)
        f.write("\n")
    return manifest


def refresh(folder, note):
    """Lists the folder's files anew in its manifest, keeping what it records about the runs
    (commit, command, protocol, date, machine) and adding ``note`` (what changed the files, e.g.
    figures redrawn from the same data by a later commit). Returns the manifest."""
    with open(os.path.join(folder, NAME)) as f:
        old = json.load(f)
    if not (isinstance(note, str) and note):
        raise ValueError("note: a non-empty string (what changed the files)")
    return write(folder, old["commit"], old["command"], old.get("protocol"), old.get("date"),
                 "; ".join(x for x in (old.get("note"), note) if x), old.get("machine"))


def check(folder):
    """The differences between ``folder`` and its manifest: a list of 'missing F', 'changed F',
    'unlisted F' (empty: the folder holds exactly what the manifest says)."""
    with open(os.path.join(folder, NAME)) as f:
        listed = json.load(f)["files"]
    present = set(files_of(folder))
    problems = [f"missing {f}" for f in sorted(set(listed) - present)]
    problems += [f"unlisted {f}" for f in sorted(present - set(listed))]
    problems += [f"changed {f}" for f in sorted(set(listed) & present)
                 if os.path.getsize(os.path.join(folder, f)) != listed[f]["bytes"]
                 or digest(os.path.join(folder, f)) != listed[f]["sha256"]]
    return problems


def main(argv):
    import argparse
    p = argparse.ArgumentParser(prog="python3 -m mesostudies.manifest", description=__doc__.split("\n\n")[0])
    p.add_argument("folder")
    p.add_argument("--check", action="store_true", help="compare the folder with its manifest")
    p.add_argument("--commit")
    p.add_argument("--command")
    p.add_argument("--protocol", default=None, help="the preparation, as JSON")
    p.add_argument("--date", default=None)
    p.add_argument("--note", default=None)
    p.add_argument("--machine", default=None, help="the machine that ran it (default: this one's processor and cores)")
    p.add_argument("--refresh", default=None, metavar="NOTE",
                   help="list the files anew, keeping the recorded commit, command, protocol, date and machine, "
                        "and add NOTE (what changed them)")
    a = p.parse_args(argv)
    if a.check:
        problems = check(a.folder)
        print("\n".join(problems) or f"{a.folder}: as its manifest says")
        return 1 if problems else 0
    try:
        if a.refresh is not None:
            m = refresh(a.folder, a.refresh)
            print(f"{a.folder}/{NAME}: {len(m['files'])} files (refreshed)")
            return 0
        protocol = json.loads(a.protocol) if a.protocol else None
        m = write(a.folder, a.commit, a.command, protocol, a.date, a.note, a.machine)
    except (ValueError, json.JSONDecodeError) as e:
        p.error(str(e))
    print(f"{a.folder}/{NAME}: {len(m['files'])} files")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
