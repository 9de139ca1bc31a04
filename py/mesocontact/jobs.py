"""A study's jobs behind one command line (plain Python, no YADE): each job a record, the
registry of them declared once, in the module above the job modules (it imports them; they never
import it).

    JOBS = Registry([
        Job("prepare", prepare, "the sample, made once and cached."),
        Job("pull", pull, "the pull to rupture.", cost=pull_steps),
    ])
    JOBS.get(name).function(options)     # ValueError naming the job and the known ones
    JOBS.cost(name, *args)               # the job's estimate (None without one); unknown: ValueError
    JOBS.describe()                      # one line per job, for --help

A registry iterates over its names in their order and answers ``name in JOBS``, so that it is
argparse's ``choices`` as it stands."""
import textwrap
from dataclasses import dataclass
from typing import Callable, Optional


@dataclass(frozen=True)
class Job:
    """One job: its ``name`` (the command line's word: no blanks, not an option), the ``function``
    that runs it, a one-line ``description`` and, optionally, a ``cost`` function (an estimate
    of its work, in units its study's plan chooses)."""
    name: str
    function: Callable
    description: str
    cost: Optional[Callable] = None

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name or self.name.startswith("-") or \
                any(c.isspace() for c in self.name):
            raise ValueError(f"name = {self.name!r} is invalid: a word, not an option (no blanks, no leading '-')")
        if not callable(self.function):
            raise ValueError(f"function = {self.function!r} is invalid (job {self.name!r}): not callable")
        if not isinstance(self.description, str) or not self.description.strip() or "\n" in self.description:
            raise ValueError(f"description = {self.description!r} is invalid (job {self.name!r}): one line of text")
        if self.cost is not None and not callable(self.cost):
            raise ValueError(f"cost = {self.cost!r} is invalid (job {self.name!r}): None or callable")


class Registry:
    """A study's jobs in their order (a sequence of Job; ``what``: what they are called in messages)."""

    def __init__(self, jobs, what="job"):
        self.what = what
        self._jobs = {}
        for job in jobs:
            if not isinstance(job, Job):
                raise ValueError(f"jobs: {job!r} is invalid: a Job")
            if job.name in self._jobs:  # the second would shadow the first without a word
                raise ValueError(f"jobs: two {what}s named {job.name!r}")
            self._jobs[job.name] = job
        if not self._jobs:
            raise ValueError("jobs is invalid: empty")

    def __iter__(self):
        return iter(self._jobs)

    def __len__(self):
        return len(self._jobs)

    def __contains__(self, name):
        try:
            return name in self._jobs
        except TypeError:  # an unhashable name (argparse's choices may ask) is simply not a job
            return False

    def names(self):
        return tuple(self._jobs)

    def get(self, name):
        """The Job named ``name``; ValueError naming it and the known ones."""
        try:
            return self._jobs[name]
        except (KeyError, TypeError):  # TypeError: an unhashable name is unknown too
            raise ValueError(f"{self.what} {name!r} is unknown: one of {', '.join(self._jobs)}") from None

    def cost(self, name, *args, **kwargs):
        """The estimate of job ``name`` (its cost function called with the arguments), None if it
        declares none; an unknown job is a ValueError, never a zero."""
        job = self.get(name)
        return None if job.cost is None else job.cost(*args, **kwargs)

    def describe(self, indent=2, width=100):
        """The list for --help: each job's name and its description beside it, wrapped to ``width``
        columns under the descriptions' common left edge."""
        left = indent + max(len(n) for n in self._jobs) + 2
        lines = [textwrap.fill(j.description, width, initial_indent=" " * indent + j.name.ljust(left - indent),
                               subsequent_indent=" " * left, break_on_hyphens=False) for j in self._jobs.values()]
        return "\n".join(lines)
