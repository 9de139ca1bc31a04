"""yade-batch support: a script that takes command-line options also runs as a yade-batch job,
its options then coming from the job's line of the parameter table (inside ``yade``).

    argv = batch.argv(sys.argv[1:], positional="number", number=None, paper="long", quick=False)

Run alone, argv is the command line. Under yade-batch (which sets YADE_BATCH), the table's
columns are read with ``yade.utils.readParamsFromTable`` (the keywords are the columns a table
may have, with their defaults; an unknown column fails the job naming it) and turned into the
same options: ``name=value`` becomes ``--name value`` (underscores as dashes), a True flag
``--name``, a False or None one nothing, and the column named by ``positional`` (if any) the
leading positional argument."""
import os


def under_batch():
    """Whether yade-batch started this process (it names the table line in YADE_BATCH)."""
    return bool(os.environ.get("YADE_BATCH"))


def check_descriptions():
    """Under yade-batch: two lines of one table with one description write one set of result files
    (the job's name), the second job silently overwriting the first's. Refused (ValueError), naming
    the lines; nothing outside yade-batch. A job script calls it first (argv does)."""
    if not under_batch():
        return
    from yade.utils import TableParamReader
    table, _, line = os.environ["YADE_BATCH"].rpartition(":")
    if not (table and os.path.exists(table)):
        return
    rows = TableParamReader(table).paramDict()
    mine = rows.get(int(line), {}).get("description") if line.isdigit() else None
    same = sorted(n for n, r in rows.items() if mine is not None and r.get("description") == mine)
    if len(same) > 1:
        raise ValueError(f"{table}: lines {', '.join(map(str, same))} share the description {mine!r}: their jobs would "
                         "write the same result files; give each line its own description")


def argv(command_line, positional=None, **columns):
    if not under_batch():
        return list(command_line)
    from yade import utils
    check_descriptions()
    utils.readParamsFromTable(noTableOk=True, **columns)
    from yade.params import table
    out = []
    for name in columns:
        value = getattr(table, name)
        if name == positional:
            out = ([] if value is None else [str(value)]) + out
        elif value is True:
            out.append("--" + name.replace("_", "-"))
        elif value is False or value is None:
            continue
        else:
            out += ["--" + name.replace("_", "-"), str(value)]
    print(f"[batch] {os.environ['YADE_BATCH']}: options {' '.join(out)}", flush=True)
    return out


def help_requested(argv, script, nargs=None, more=None):
    """A script's --help (or -h): prints its header comment (its usage), then ``more`` if given
    (e.g. a job registry's describe()), and ends the process with status 0; with ``nargs``, a
    wrong count of positional arguments prints it and ends with status 2. ``script`` is
    sys.argv[0], the script's path under ``yade -x``."""
    import sys
    asked = bool(set(argv) & {"-h", "--help"})
    wrong = not asked and nargs is not None and not under_batch() and len([a for a in argv
                                                                           if not a.startswith("-")]) != nargs
    if not asked and not wrong:
        return
    with open(script) as f:
        head = [ln[2:].rstrip() if ln.startswith("# ") else ln[1:].rstrip() for ln in f
                if ln.startswith("#") and not ln.startswith("#!")]
    text = "\n".join(head[:40]) or f"usage: yade -n -x {script}"
    if more:
        text += "\n" + more
    if wrong:
        print(f"{script}: expected {nargs} argument(s), got {argv}\n{text}", file=sys.stderr, flush=True)
        sys.exit(2)
    print(text, flush=True)
    sys.exit(0)
