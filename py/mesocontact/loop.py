"""Python called from inside YADE's loop, one way for the whole package.

A PyRunner runs a command string in yade's ``__main__``. ``runner(fn, period, label)`` keeps
``fn`` in this module's registry under ``label`` and gives a PyRunner whose command calls it from
there, so no name is left in ``builtins`` or ``__main__``, and the callable may be a closure over
its own state. ``register`` changes what a label's runner calls (e.g. a driver's next phase).

A scene saved with such a runner and loaded in another process finds its label unregistered; the
runner then stops the run with a ``RuntimeError`` that names the label (install it again after
``O.load``).
"""

_CALLBACKS = {}
_COMMAND = "__import__('mesocontact.loop').loop.call(%r)"


def runner(fn, period, label):
    """A PyRunner (labelled ``label``) calling ``fn()`` every ``period`` steps (an integer >= 1).
    YADE makes a label a global name, so a label that already names something else (``O``,
    ``sphere``, a builtin) is refused."""
    import numbers
    from yade import wrapper as w
    if isinstance(period, bool) or not isinstance(period, numbers.Integral) or not 1 <= period <= 2 ** 31 - 1:
        raise ValueError(f"period = {period!r} is invalid: must be an integer number of steps in [1, 2**31 - 1]")
    _check_free(label)
    register(label, fn)
    return w.PyRunner(iterPeriod=period, command=_COMMAND % label, label=label)


def _check_free(label):
    """A label YADE may make global: not a name of builtins, of yade or of the running script's
    globals, unless it is one of this registry's runners or names a PyRunner (a loaded scene's,
    installed again)."""
    import builtins
    import sys
    from yade import wrapper as w
    if not isinstance(label, str) or not label.isidentifier() or label in _CALLBACKS:
        return  # register() names a bad label; one of ours may be installed again
    taken = [where for where, space in (("builtins", vars(builtins)), ("yade", vars(sys.modules.get("yade", builtins))),
                                        ("__main__", vars(sys.modules["__main__"])))
             if label in space and not isinstance(space[label], w.PyRunner)]
    if taken:
        raise ValueError(f"label = {label!r} is invalid: YADE makes a label a global name, and {label!r} already names "
                         f"something in {', '.join(taken)}; choose another")


def register(label, fn):
    """Makes the runner labelled ``label`` call ``fn()`` from now on."""
    if not isinstance(label, str) or not label.isidentifier():
        raise ValueError(f"label = {label!r}: must be a Python identifier (it is the PyRunner's label too)")
    if not callable(fn):
        raise TypeError(f"fn = {fn!r}: must be callable")
    _CALLBACKS[label] = fn


def call(label):
    """What the runner's command does (inside YADE's loop)."""
    try:
        fn = _CALLBACKS[label]
    except KeyError:
        raise RuntimeError(f"PyRunner {label!r}: no callable registered under this label in this process "
                           f"(a scene loaded from a file? install its runner again with mesocontact.loop.runner)") from None
    fn()


def registered():
    """The labels with a callable, for checks and tests."""
    return sorted(_CALLBACKS)
