# ctest (inside yade): the one way the package calls Python from YADE's loop (mesocontact.loop):
# a registered callable runs as often as a plain PyRunner of the same period, its label can be
# re-pointed, nothing is left in builtins or __main__ (a pair collision, which uses it, included),
# an unregistered label stops the run naming it, bad labels are refused; and mesocontact.mpi's
# check of the yade.mpy functions it replaces. KeyboardInterrupt and SystemExit in a callback, in a
# YADE subprocess with a timeout (issue #57 item 4): the first left a half-done step that the next
# O.run repeated, the second hung the process in O.run; now the step completes, KeyboardInterrupt
# pauses the run (O.run goes on, no step repeated) and SystemExit ends the process with its code.
import builtins
import json
import os
import subprocess
import sys
import tempfile
import time
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
left = sorted((set(dir(builtins)) - before["builtins"] - labels) | (set(vars(__main__)) - before["main"] - labels
                                                                    - {"e", "before", "labels"}))
check(not left, "no name left in builtins or __main__ but the runners' labels", left)

# A registered callable against a plain PyRunner of the same period (its own counter in __main__).
O.reset()
calls = []
__main__._plain_count = 0
O.engines = [loop.runner(lambda: calls.append(O.iter), 3, "counter"),
             w.PyRunner(iterPeriod=3, command="import __main__; __main__._plain_count += 1")]
O.run(20, True)
check(len(calls) == __main__._plain_count > 0,
      f"called {len(calls)} times in 20 steps, as a plain PyRunner ({__main__._plain_count})")
check(O.engines[0].label == "counter" and "counter" in loop.registered(),
      "the PyRunner carries the label it is registered under")
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
    check("counter" in str(e) and "registered" in str(e), "an unregistered label stops the run, naming it",
          str(e)[:160])
for label, fn, error in (("two words", print, ValueError), (5, print, ValueError), ("ok", None, TypeError)):
    try:
        loop.register(label, fn)
        check(False, f"register({label!r}, {fn!r}) refused", "accepted")
    except error as e:
        check(str(e).startswith("label" if error is ValueError else "fn"),
              f"register({label!r}, ...) refused naming it", str(e))

# mesocontact.mpi replaces two yade.mpy functions: their parameters are checked first.
good = dict(parallelCollide=lambda: None, reallocateBodiesToSubdomains=lambda _filter=None, blocking=True: None)
check(mpi.check_mpy(types.SimpleNamespace(**good)) == config.version, "this YADE's mpy signatures pass")
for change, words in ((dict(parallelCollide=lambda steps: None),
                       f"parallelCollide of YADE {config.version} is (steps)"),
                      (dict(reallocateBodiesToSubdomains=None),
                       f"reallocateBodiesToSubdomains of YADE {config.version} is missing")):
    try:
        mpi.check_mpy(types.SimpleNamespace(**dict(good, **change)))
        check(False, f"an mpy with {words} refused", "accepted")
    except RuntimeError as e:
        check(words in str(e), f"refused: {e}")

# KeyboardInterrupt and SystemExit in a callback: the runner after Newton, so a half-done step (Newton
# applied, O.iter not advanced) shows as a repeated step in the falling sphere's velocity.
CHILD = '''
import atexit, json, sys
from yade import O, utils
from yade import wrapper as w
from mesocontact import loop
how, fail_at = sys.argv[1], int(sys.argv[2])
seen = []

def build(stop):
    O.reset()
    O.bodies.append(utils.sphere((0, 0, 0), 1e-3))
    O.dt = 1e-3
    seen.clear()
    def callback():
        seen.append(O.iter)
        if O.iter == stop:
            raise {"interrupt": KeyboardInterrupt, "exit": SystemExit(7)}[how.split("-")[0]]
    O.engines = [w.ForceResetter(), w.NewtonIntegrator(damping=0, gravity=(0, 0, -10)), loop.runner(callback, 1, "probeStop")]

def outcome():
    return [O.iter, list(O.bodies[0].state.vel), list(O.bodies[0].state.pos)]

build(None)
O.run(20, True)
reference = outcome()
build(fail_at)
atexit.register(lambda: print("ATEXIT " + json.dumps(outcome()), flush=True))
result = {}
try:
    if how.endswith("run"):
        O.run(20, True)
        result["after_run"] = outcome()
        result["running"] = O.running
        O.run(20 - O.iter, True)
    else:
        for _ in range(40):  # a caller's O.step() loop that goes on after an error
            if O.iter == 20:
                break
            try:
                O.step()
            except RuntimeError as e:
                result.setdefault("errors", []).append([O.iter, str(e)[:300]])
finally:
    print("FINALLY", flush=True)
result.update(final=outcome(), reference=reference, seen=seen)
print("RESULT " + json.dumps(result), flush=True)
'''  # noqa: E501 (the child's script, kept as it was)
child = os.path.join(tempfile.mkdtemp(prefix="loop-stop-"), "child.py")
with open(child, "w") as f:
    f.write(CHILD)
launcher = os.path.abspath("yade-meso")  # ctest runs this from the build directory
if not os.path.exists(launcher):
    launcher = sys.argv[0]


def child_run(how, fail_at=5):
    t0 = time.time()
    try:
        p = subprocess.run([launcher, "-j1", "-n", "-x", child, how, str(fail_at)], capture_output=True, text=True,
                           timeout=120)
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
        return None, out, time.time() - t0
    return p.returncode, p.stdout + p.stderr, time.time() - t0


def result_of(text):
    lines = [line for line in text.splitlines() if line.startswith("RESULT ")]
    return json.loads(lines[-1][7:]) if lines else None


rc, text, secs = child_run("interrupt-run")
r = result_of(text)
check(rc == 0 and r is not None and r["after_run"][0] == 6 and not r["running"],
      "KeyboardInterrupt in O.run: the step completed (O.iter 6 after failing at 5) and the run paused",
      f"rc {rc}, {r and r['after_run'][0]}, {secs:.0f} s" if r else f"rc {rc}: {text[-300:]}")
check(r is not None and r["final"] == r["reference"] and r["seen"] == list(range(1, 20)),
      "O.run after the interrupt goes on: the uninterrupted run to the bit, no step repeated",
      f"{r and r['final']} against {r and r['reference']}, callback at {r and r['seen']}")
check("KeyboardInterrupt" in text and "paused" in text, "the pause is announced on stderr")
rc, text, secs = child_run("interrupt-step")
r = result_of(text)
errors = r.get("errors", []) if r else []
check(rc == 0 and len(errors) == 1 and errors[0][0] == 6 and "KeyboardInterrupt" in errors[0][1],
      "KeyboardInterrupt under O.step(): the step completes, the next O.step() stops with it before any engine acts",
      str(errors)[:200] if r else f"rc {rc}: {text[-300:]}")
check(r is not None and r["final"] == r["reference"] and r["seen"] == list(range(1, 20)),
      "O.step() on after it: the uninterrupted run to the bit, no step repeated", f"{r and r['final']}")
for how in ("exit-run", "exit-step"):
    rc, text, secs = child_run(how)
    done = [line for line in text.splitlines() if line.startswith("ATEXIT ")]
    check(rc == 7 and "RESULT " not in text and secs < 120,
          f"SystemExit(7) in a callback under {'O.run' if how == 'exit-run' else 'O.step()'} ends the "
          f"process with code 7",
          f"rc {rc} ({'timed out: hung' if rc is None else 'exited'}) after {secs:.0f} s")
    if how == "exit-run":
        check("FINALLY" in text and done and json.loads(done[-1][7:])[0] == 6,
              "... as sys.exit does in the script: finally and atexit run, the step completed (O.iter 6)",
              done[-1:] or text[-200:])
finish()
