# ctest (inside yade): invalid parameters raise a Python ValueError naming the parameter, in
# the constructor and on assignment; a rejected assignment leaves the material as it was, so
# a simulation with it gives finite forces.
import math

from yade import *
from mesocontact import pair
from harness import check, failures, finish

nan = float("nan")
cases = [
    (dict(k1=100, kp=50), "kp"),
    (dict(k1=-1), "k1"),
    (dict(kc=-5), "kc"),
    (dict(phiF=0), "phiF"),
    (dict(phiF=1.01), "phiF"),
    (dict(fa=1e-3, kca=0, adhesion="reversible"), "kca"),
    (dict(fa=1e-3, kca=-2, adhesion="jumpIn"), "kca"),
    (dict(fa=1e-3, kca=10), "adhesion"),
    (dict(adhesion="jump-in"), "adhesion"),
    (dict(k2Interpolation="cubic"), "k2Interpolation"),
    (dict(k1=nan), "k1"),
    (dict(kp=nan), "kp"),
    (dict(gammaN=nan), "gammaN"),
    (dict(fa=nan, adhesion="reversible", kca=1), "fa"),
    (dict(gammaN=-1e-3), "gammaN"),
    (dict(kt=-1), "kt"),
    (dict(gammaT=nan), "gammaT"),
    (dict(kr=float("inf")), "kr"),
    (dict(muR=-0.1), "muR"),
    (dict(ko=-5), "ko"),
    (dict(gammaO=-1), "gammaO"),
    (dict(muO=nan), "muO"),
    (dict(phiD=0), "phiD"),
    (dict(phiD=1.2), "phiD"),
    (dict(frictionAngle=-0.1), "frictionAngle"),
    (dict(frictionAngle=2.0), "frictionAngle"),
    # not the law's, but read by YADE (PWaveTimeStep; FrictMat laws take poisson as ks/kn): issue #57
    (dict(young=1e300), "young"),
    (dict(young=1e-300), "young"),
    (dict(poisson=nan), "poisson"),
    (dict(poisson=float("inf")), "poisson"),
    (dict(poisson=3.0), "poisson"),
    (dict(poisson=-0.1), "poisson"),
]
for kw, name in cases:
    try:
        MesoMat(**kw)
        failures.append(f"constructor {kw}: no exception")
    except ValueError as e:
        if not str(e).startswith(name):
            failures.append(f"constructor {kw}: message does not name {name}: {e}")
    if len(kw) > 1:
        continue  # combined cases are checked by the constructor, which applies all keywords first
    m = MesoMat(k1=100, kp=500, kc=100)
    before = {a: getattr(m, a) for a in ("k1", "kp", "kc", "phiF", "fa", "kca", "gammaN", "adhesion",
                                         "k2Interpolation")}
    try:
        setattr(m, name, kw[name])
        failures.append(f"assignment {kw}: no exception")
    except ValueError as e:
        if not str(e).startswith(name):
            failures.append(f"assignment {kw}: message does not name {name}: {e}")
    after = {a: getattr(m, a) for a in before}
    if after != before:
        failures.append(f"assignment {kw}: the material changed: {after}")

# Inherited attributes of a wrong type name themselves (not Boost's "None.None(...)").
for name, value in (("poisson", "abc"), ("label", 3), ("id", 1.5), ("young", "x")):
    m = MesoMat()
    try:
        setattr(m, name, value)
        failures.append(f"{name} = {value!r}: no exception")
    except TypeError as e:
        if not str(e).startswith(name):
            failures.append(f"{name} = {value!r}: message does not name it: {e}")
# Every class of the plugin: a misspelt name, a read-only attribute, a wrong type named; updateAttrs all or nothing.
for make, name, value, error in ((Ip2_MesoMat_MesoMat_MesoPhys, "K1", 5.0, AttributeError),
                                 (Law2_ScGeom_MesoPhys_Meso, "label", 3, TypeError),
                                 (Ip2_MesoMat_MesoMat_MesoPhys, "stableDt", 1.0, AttributeError),
                                 (MesoPhys, "deltaMax", 0.0, AttributeError),
                                 (Ig2_Facet_Sphere_MesoScGeom, "interactionDetectionFactor", [1.0], TypeError),
                                 (MesoBackgroundDamping, "dead", 1, TypeError), (MesoMat, "K1", 5.0, AttributeError),
                                 (MesoPhys, "shearForce", 1e155, TypeError)):
    obj = make()
    try:
        setattr(obj, name, value)
        failures.append(f"{make.__name__}.{name} = {value!r}: no exception")
    except error as e:
        if name not in str(e):
            failures.append(f"{make.__name__}.{name} = {value!r}: message does not name it: {e}")
law = Law2_ScGeom_MesoPhys_Meso(label="before")
try:
    law.updateAttrs({"label": "after", "nonexistent": 1.0})
    failures.append("updateAttrs with an unknown key: no exception")
except AttributeError:
    if law.label != "before":
        failures.append(f"updateAttrs refused but set label: {law.label!r}")
try:
    Ip2_MesoMat_MesoMat_MesoPhys(stableDt=1.0)
    failures.append("Ip2(stableDt=1.0): no exception")
except ValueError as e:
    if "stableDt" not in str(e):
        failures.append(f"Ip2(stableDt=1.0) does not name it: {e}")
m = MesoMat(label="powder", poisson=0.3)
m.label, m.id = "powder2", 4
if (m.label, m.id, m.poisson) != ("powder2", 4, 0.3):
    failures.append(f"valid label, id, poisson not kept: {m.label!r}, {m.id!r}, {m.poisson!r}")

# The lever-arm convention of the Ip2.
try:
    Ip2_MesoMat_MesoMat_MesoPhys(leverArm="diameter")
    failures.append("leverArm: no exception")
except ValueError as e:
    if not str(e).startswith("leverArm"):
        failures.append(f"leverArm: message does not name it: {e}")
ip2 = Ip2_MesoMat_MesoMat_MesoPhys(leverArm="a12")
try:
    ip2.leverArm = "x"
    failures.append("leverArm = 'x' on assignment: no exception")
except ValueError:
    pass
if ip2.leverArm != "a12":
    failures.append(f"leverArm: rejected value kept ({ip2.leverArm})")

# Order of keywords does not matter in the constructor.
MesoMat(kp=5000, k1=1000)
MesoMat(adhesion="reversible", fa=1e-3, kca=10)

# A material whose bad assignment was rejected still simulates with finite forces.
m = MesoMat(k1=100, kp=500, kc=100, density=2000)
try:
    m.kp = nan
except ValueError:
    pass
s = pair.build(1e-3, 0.05, m)
finite = True
for _ in range(2000):
    O.step()
    for i in O.interactions:
        finite = finite and all(math.isfinite(x) for x in i.phys.normalForce)
if not finite:
    failures.append("non-finite force after a rejected assignment")
check(True, f"{len(cases)} invalid cases, constructor and assignment, were run")
for f in failures:
    print("FAIL", f)
finish()
