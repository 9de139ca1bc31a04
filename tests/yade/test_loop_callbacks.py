# ctest (inside yade): the one way the package calls Python from YADE's loop (mesocontact.loop):
# a registered callable runs as often as a plain PyRunner of the same period, its label can be
# re-pointed, nothing is left in builtins or __main__ (a pair collision, which uses it, included),
# an unregistered label stops the run naming it, bad labels are refused; and mesocontact.mpi's
# check of the yade.mpy functions it replaces.
import builtins
import types

import __main__
from yade import O
from yade import wrapper as w
from yade import config
from mesocontact import loop, mpi, pair
from harness import check, finish



def one_collision():
    s = pair.build(1e-3, 0.1, dict(k1=100.0, kp=500.0))
    return pair.collide(s).e


def a_scene_runner():  # as the tablet's servo, recorder and wall work install theirs
    O.engines = O.engines + [loop.runner(lambda: None, 1, "sceneRunner")]
    O.run(3, True)


before = {"builtins": set(dir(builtins)), "main": set(vars(__main__))}
e = one_collision()
a_scene_runner()
check(0 < e < 1, f"a pair collision through the registry: e = {e:.4f}")
# YADE itself makes every engine's label a global name (its label mechanism): the labels only.
labels = {"pairWatcher", "sceneRunner"}
left = sorted((set(dir(builtins)) - before["builtins"] - labels) | (set(vars(__main__)) - before["main"] - labels - {"e", "before", "labels"}))
check(not left, "no name left in builtins or __main__ but the runners' labels", left)

# A registered callable against a plain PyRunner of the same period (its own counter in __main__).
O.reset()
calls = []
__main__._plain_count = 0
O.engines = [loop.runner(lambda: calls.append(O.iter), 3, "counter"),
             w.PyRunner(iterPeriod=3, command="import __main__; __main__._plain_count += 1")]
O.run(20, True)
check(len(calls) == __main__._plain_count > 0, f"called {len(calls)} times in 20 steps, as a plain PyRunner ({__main__._plain_count})")
check(O.engines[0].label == "counter" and "counter" in loop.registered(), "the PyRunner carries the label it is registered under")
other, first, plain_first = [], len(calls), __main__._plain_count
loop.register("counter", lambda: other.append(O.iter))
O.run(20, True)
check(len(other) == __main__._plain_count - plain_first > 0 and len(calls) == first,
      f"re-pointed: the new callable ran {len(other)} times as the plain one, the old one no more")
del __main__._plain_count

# An unregistered label (a scene loaded in another process) stops the run with its name, at the
# start of the step after the one it failed in (that step completed; mesocontact.loop).
O.engines = O.engines[:1]  # the plain runner's counter is gone
loop._CALLBACKS.pop("counter")
try:
    for _ in range(4):
        O.step()
    check(False, "an unregistered label stops the run", "ran")
except Exception as e:  # noqa: BLE001 - the message is what is checked
    check("counter" in str(e) and "registered" in str(e), "an unregistered label stops the run, naming it", str(e)[:160])
for label, fn, error in (("two words", print, ValueError), (5, print, ValueError), ("ok", None, TypeError)):
    try:
        loop.register(label, fn)
        check(False, f"register({label!r}, {fn!r}) refused", "accepted")
    except error as e:
        check(str(e).startswith("label" if error is ValueError else "fn"), f"register({label!r}, ...) refused naming it", str(e))

# mesocontact.mpi replaces two yade.mpy functions: their parameters are checked first.
good = dict(parallelCollide=lambda: None, reallocateBodiesToSubdomains=lambda _filter=None, blocking=True: None)
check(mpi.check_mpy(types.SimpleNamespace(**good)) == config.version, "this YADE's mpy signatures pass")
for change, words in ((dict(parallelCollide=lambda steps: None), f"parallelCollide of YADE {config.version} is (steps)"),
                      (dict(reallocateBodiesToSubdomains=None), f"reallocateBodiesToSubdomains of YADE {config.version} is missing")):
    try:
        mpi.check_mpy(types.SimpleNamespace(**dict(good, **change)))
        check(False, f"an mpy with {words} refused", "accepted")
    except RuntimeError as e:
        check(words in str(e), f"refused: {e}")
finish()
