# ctest (inside yade): the parameters generated from `pkg/core/MesoParamTable.hpp`: every number of
# `MesoMat` (the list is read from `MesoMat` itself, so a new parameter without a rule here fails)
# reaches its contacts by the rule the docs state, written out here independently (harmonic,
# arithmetic or smaller mean), `muD = phiD muS`, is refused by name when invalid, kept by
# `O.save`/`O.load` in both formats, and a file of the first `PairParams` layout
# (`tests/yade/golden/pairparams_v0.*`, written by 20d0512) loads with `phiD` recovered and `gammaN2` 0;
# one of the layout just before `gammaN2` (`pairparams_v1.*`, add2ac8) loads as saved, `gammaN2` 0.
import json
import math
import os
import tempfile

from yade import O
from yade import wrapper as w
from harness import check, finish
from golden.pairparams_v0 import contact

HERE = os.path.dirname(os.path.abspath(__import__("harness").__file__))


def harmonic(x, y):
    return 0.0 if x == 0 or y == 0 else 2 * x * y / (x + y)


# name -> (rule, value of material A, value of material B); A's and B's values all differ.
RULES = {"k1": (harmonic, 100.0, 150.0), "kp": (harmonic, 500.0, 650.0), "kc": (harmonic, 50.0, 80.0),
         "phiF": (lambda x, y: 0.5 * (x + y), 0.1, 0.3), "fa": (harmonic, 1e-4, 3e-4), "kca": (harmonic, 100.0, 40.0),
         "gammaN": (harmonic, 1e-3, 3e-3), "gammaN2": (harmonic, 2e-2, 5e-2), "phiD": (min, 0.9, 0.6),
         "kt": (harmonic, 40.0, 70.0),
         "gammaT": (harmonic, 1e-3, 4e-3), "kr": (harmonic, 20.0, 35.0), "gammaR": (harmonic, 5e-4, 2e-3),
         "muR": (min, 0.3, 0.1), "ko": (harmonic, 25.0, 10.0), "gammaO": (harmonic, 6e-4, 1e-3),
         "muO": (min, 0.05, 0.2)}
numbers = sorted(k for k, v in w.MesoMat().dict().items() if isinstance(v, float) and k not in ("density", "young",
                                                                                                "poisson",
                                                                                                "frictionAngle"))
check(numbers == sorted(RULES), "every number of MesoMat has its rule here", f"MesoMat: {numbers}")

mat_a = dict({k: v[1] for k, v in RULES.items()}, adhesion="reversible", density=2000.0, frictionAngle=math.atan(0.5))
mat_b = dict({k: v[2] for k, v in RULES.items()}, adhesion="reversible", density=2000.0, frictionAngle=math.atan(0.3))


i = contact(mat_a, mat_b, 200, angVel=(1, 2, 3), vel=(0.01, 0.003, 0), overlap=2e-6)
p = i.phys
for name, (rule, x, y) in RULES.items():
    want = rule(x, y)
    check(abs(getattr(p, name) - want) <= 1e-15 * abs(want), f"MesoPhys.{name} = its rule of A and B",
          f"{getattr(p, name)!r} vs {want!r}")
mu_s = min(math.tan(mat_a["frictionAngle"]), math.tan(mat_b["frictionAngle"]))
check(p.muS == mu_s, "MesoPhys.muS = the smaller tan(frictionAngle)", f"{p.muS!r} vs {mu_s!r}")
mixed = O.engines[2].physDispatcher.functors[0].mixedParameters(O.materials[0], O.materials[1])
check(abs(mixed["torsion"]["muD"] - 0.6 * 0.05) < 1e-17 and abs(mixed["sliding"]["muD"] - 0.6 * p.muS) < 1e-17,
      "muD = phiD muS for sliding and torsion", f"{mixed['sliding']['muD']}, {mixed['torsion']['muD']}")

for name in RULES:
    m = w.MesoMat()
    try:
        setattr(m, name, -1.0)
        check(False, f"MesoMat.{name} = -1 refused", "accepted")
    except ValueError as e:
        check(str(e).startswith(f"{name} = -1 is invalid"), f"MesoMat.{name} = -1: ValueError naming it", str(e))

props = list(RULES) + ["muS", "deltaMax", "delta0", "torsionSpring", "coulombLevel"]
before = {k: getattr(p, k) for k in props}
for ext in (".yade.gz", ".xml"):
    path = os.path.join(tempfile.mkdtemp(), "state" + ext)
    O.save(path)
    O.load(path)
    q = O.interactions[0, 1].phys
    diff = [k for k in props if getattr(q, k) != before[k]]
    check(not diff, f"O.save/O.load ({ext}) keeps every parameter and the history", f"differ: {diff}")

# The first layout: phiD is recovered from the elements (muD/muS); the rest reads as written.
with open(os.path.join(HERE, "golden", "pairparams_v0.json")) as f:
    ref = json.load(f)
O.load(os.path.join(HERE, "golden", "pairparams_v0.yade.gz"))
q = O.interactions[0, 1].phys
diff = [k for k, v in ref["contact"].items() if (list(getattr(q, k)) if isinstance(v, list) else getattr(q, k)) != v]
check(not diff, f"a version-0 file (written by {ref['written_by']}) loads with its contact as saved", f"differ: {diff}")
check(abs(q.phiD - ref["phiD_of_the_pair"]) < 1e-15, "a version-0 file: phiD recovered from muD/muS", repr(q.phiD))
# Written before gammaN2 (MesoMat version 0, PairParams version 0): both read it as 0, the law of then
check(q.gammaN2 == 0.0 and all(m.gammaN2 == 0.0 for m in O.materials), "a version-0 file: gammaN2 = 0 in the contact "
      "and every material", f"{q.gammaN2!r}, {[m.gammaN2 for m in O.materials]}")
O.run(10, True)
check(O.interactions[0, 1].isReal, "a version-0 file runs on")

# The layout just before gammaN2 (PairParams version 1, MesoMat version 0): everything as saved, gammaN2 = 0
with open(os.path.join(HERE, "golden", "pairparams_v1.json")) as f:
    ref = json.load(f)
O.load(os.path.join(HERE, "golden", "pairparams_v1.yade.gz"))
q = O.interactions[0, 1].phys
diff = [k for k, v in ref["contact"].items() if (list(getattr(q, k)) if isinstance(v, list) else getattr(q, k)) != v]
diff += [f"material {i}: {k}" for i, m in enumerate(ref["materials"]) for k, v in m.items()
         if getattr(O.materials[i], k) != v]
check(not diff, f"a version-1 file (written by {ref['written_by']}) loads with its contact and materials as saved",
      f"differ: {diff}")
check(q.gammaN2 == 0.0 and all(m.gammaN2 == 0.0 for m in O.materials), "a version-1 file: gammaN2 = 0")
O.run(10, True)
check(O.interactions[0, 1].isReal, "a version-1 file runs on")
finish()
