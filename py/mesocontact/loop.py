"""Python called from inside YADE's loop, one way for the whole package.

A PyRunner runs a command string in yade's ``__main__``. ``runner(fn, period, label)`` keeps
``fn`` in this module's registry under ``label`` and gives a PyRunner whose command calls it from
there, so no name is left in ``builtins`` or ``__main__``, and the callable may be a closure over
its own state. ``register`` changes what a label's runner calls (e.g. a driver's next phase).

A callable that raises does not leave a half-applied step (YADE stops at the failing engine, so
the engines before it would run twice when the run resumes): the step is completed, the error is
printed at once, and the run stops at the start of the next step with a ``RuntimeError`` that
names the runner, the iteration and the error, before any engine of that step acts. Resuming
after a fix (``register`` or ``runner`` again, then ``O.run``) repeats no step.

A scene saved with such a runner and loaded in another process finds its label unregistered; the
runner then stops the run the same way, naming the label (install it again after ``O.load``).

``KeyboardInterrupt`` and ``SystemExit`` are requests, not errors (YADE's own PyRunner leaves a
half-done step for the first and hangs the process on the second in ``O.run``). Both let the step
complete. A ``KeyboardInterrupt`` pauses ``O.run`` after it (``O.run`` again goes on from the next
step); under ``O.step()`` there is no run to pause, so the next step's start raises it as an error
above. A ``SystemExit`` in ``O.run`` pauses the run and is raised in the main thread, where the
script's ``O.run(..., True)`` or ``O.wait()`` returns: the process ends as a script's
``sys.exit(code)`` does (``finally``, ``atexit``, its exit code); under ``O.step()`` it ends the
process at once, as YADE does.
"""

_CALLBACKS = {}
_COMMAND = "__import__('mesocontact.loop').loop.call(%r)"
_RAISE = "__import__('mesocontact.loop').loop.raise_pending()"
_PENDING = []  # (label, iteration, error) of a callback that failed: raised at the next step's start


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
        _defer(label, RuntimeError(f"PyRunner {label!r}: no callable registered under this label in this process "
                                   f"(a scene loaded from a file? install its runner again with "
                                   f"mesocontact.loop.runner)"))
        return
    try:
        fn()
    except Exception as exc:  # noqa: BLE001 - any error of the user's callable is deferred, none is lost
        _defer(label, exc)
    except KeyboardInterrupt as exc:
        _interrupted(label, exc)
    except SystemExit as exc:
        _exit(label, exc)


def _interrupted(label, exc):
    """A stop request: this step completes (call returns), then O.run pauses. Under O.step() (not
    running) pausing does nothing and the caller's loop would go on: the next step's start raises it."""
    import sys
    from yade import O
    if not O.running:
        _defer(label, exc)
        return
    print(f"mesocontact.loop: the runner {label!r} raised KeyboardInterrupt at iteration {O.iter}: this step is "
          f"completed and the run paused; O.run goes on from the next step", file=sys.stderr, flush=True)
    O.pause()


def _exit(label, exc):
    """sys.exit() in a callback. In the main thread (O.step()) YADE's PyRunner ends the process
    itself; re-raised. In O.run's thread YADE's PyRunner would finalize Python from that thread while
    the main thread waits for the run: the process hangs. So the run pauses after this step and the
    main thread gets the SystemExit where it waits (O.run(..., True), O.wait()) and ends the process
    as a script's sys.exit does."""
    import ctypes
    import os
    import sys
    import threading
    from yade import O
    main = threading.main_thread()
    if threading.current_thread() is main:
        raise exc
    print(f"mesocontact.loop: the runner {label!r} raised SystemExit({exc.code!r}) at iteration {O.iter}: this step is "
          f"completed, the run paused and the process ends", file=sys.stderr, flush=True)
    O.pause()
    # An asynchronous exception can only be a class: one that carries this exit code.
    code = exc.code
    carrier = type("SystemExit", (SystemExit,), {"__init__": lambda self, *args: SystemExit.__init__(self, code)})
    if ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(main.ident), ctypes.py_object(carrier)) != 1:
        sys.stderr.flush()  # no main thread to hand it to: end here rather than hang
        sys.stdout.flush()
        os._exit(code if isinstance(code, int) else 1)


def _defer(label, exc):
    """Prints the error now and puts a runner first in O.engines that raises it at the start of the
    next step (this step's other engines still act)."""
    import sys
    import traceback
    from yade import O
    from yade import wrapper as w
    print(f"mesocontact.loop: the runner {label!r} raised at iteration {O.iter}; this step is completed and the run "
          f"stops before the next:", file=sys.stderr)
    traceback.print_exception(type(exc), exc, exc.__traceback__, file=sys.stderr)
    if not _PENDING:
        O.engines = [w.PyRunner(iterPeriod=1, command=_RAISE)] + [e for e in O.engines if not _is_raiser(e)]
    _PENDING.append((label, O.iter, exc))


def _is_raiser(engine):
    from yade import wrapper as w
    return isinstance(engine, w.PyRunner) and engine.command == _RAISE


def raise_pending():
    """The first engine of the step after a callback failed: removes itself and raises the error
    (a scene saved with it and loaded elsewhere, with nothing pending, just removes it)."""
    from yade import O
    O.engines = [e for e in O.engines if not _is_raiser(e)]
    if not _PENDING:
        return
    (label, it, exc), rest = _PENDING[0], len(_PENDING) - 1
    _PENDING.clear()
    more = f" (and {rest} more error{'s' if rest > 1 else ''} in that step, printed then)" if rest else ""
    todo = "run on" if isinstance(exc, KeyboardInterrupt) else "fix the callable (loop.register) and run on"
    what = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
    raise RuntimeError(f"the runner {label!r} raised at iteration {it}: {what}{more}. That step "
                       f"was completed; the run stopped before iteration {O.iter}: {todo}, no step is "
                       "repeated") from exc


def registered():
    """The labels with a callable, for checks and tests."""
    return sorted(_CALLBACKS)
