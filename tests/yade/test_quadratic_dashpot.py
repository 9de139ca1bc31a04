# ctest (inside yade): the quadratic dashpot MesoMat.gammaN2 (docs/model.md §5). Pair collisions
# against the closed form (`mesocontact.quadratic_dashpot`), |de| <= 1e-3 as for the other closed
# forms, below and beyond the plastic limit, equal and unlike materials (gammaN2 mixes harmonically);
# the energy: the impact's kinetic energy lost = mesoPlastic + mesoViscous, to 1e-3 of it; gammaN2
# survives O.save / O.load in the material and in a contact, and a collision saved halfway goes on
# bit for bit; a negative value is refused naming it. (That gammaN2 = 0 leaves the force gammaN vn to
# the last bit is the core test's, Viscous.WithoutTheQuadraticDashpot...)
import math
import os
import tempfile

from yade import O
from yade import wrapper as w
from mesocontact import pair, params, quadratic_dashpot as qd, theory
from harness import check, finish

TOL_E = 1e-3
R, RHO = 1e-3, 2000.0
LAW = dict(k1=100.0, kp=500.0, kc=0.0, phiF=0.1)
m_r = params.sphere_mass(R, RHO) / 2
v_p = theory.plastic_limit_velocity(100.0, 500.0, 0.1, R, m_r)
c_crit = 2 * math.sqrt(m_r * 100.0)  # the loading branch's critical linear damping [kg/s]


def hm(x, y):
    return 2 * x * y / (x + y)


def collide(v, mat, mat2=None, energy=False):
    s = pair.build(R, v, dict(mat, density=RHO), material2=None if mat2 is None else dict(mat2, density=RHO),
                   track_energy=energy)
    return s, pair.collide(s, max_contact_times=15)


worst = 0.0
# gammaN2 v_p is 0.05 to 2 times the critical linear damping: the dashpot takes from a few % to most of the energy
for g2v in (0.05, 0.5, 2.0):
    g2 = g2v * c_crit / v_p
    for chi in (0.3, 0.9, 2.0, 6.0):
        v = chi * v_p
        th = qd.restitution(v, 100.0, 500.0, 0.1, R, m_r, g2)
        _, res = collide(v, dict(LAW, gammaN2=g2))
        worst = max(worst, abs(res.e - th.e))
        check(abs(res.e - th.e) <= TOL_E, f"gammaN2 v_p = {g2v} c_crit, chi = {chi}",
              f"e = {res.e:.6f}, closed form {th.e:.6f}, limit branch {th.plastic_limit}")
print(f"worst |de| = {worst:.2e}")

# unlike materials: the pair's gammaN2 is the harmonic mean, and so is its e
g2a, g2b = 0.5 * c_crit / v_p, 2.0 * c_crit / v_p
s, res = collide(0.9 * v_p, dict(LAW, gammaN2=g2a), dict(LAW, gammaN2=g2b))
th = qd.restitution(0.9 * v_p, 100.0, 500.0, 0.1, R, m_r, hm(g2a, g2b))
check(abs(res.e - th.e) <= TOL_E, "unlike materials mix gammaN2 harmonically", f"e = {res.e:.6f}, {th.e:.6f}")

# the energy: what the pair lost is what the law booked as plastic and viscous
for chi in (0.9, 6.0):
    v = chi * v_p
    s, res = collide(v, dict(LAW, gammaN2=0.5 * c_crit / v_p), energy=True)
    lost = 0.5 * m_r * v * v * (1 - res.e ** 2)
    booked = O.energy["mesoPlastic"] + O.energy["mesoViscous"]
    check(abs(booked - lost) <= 1e-3 * 0.5 * m_r * v * v, f"energy at chi = {chi}",
          f"lost {lost:.6e} J, plastic + viscous {booked:.6e} J (viscous {O.energy['mesoViscous']:.3e})")
    check(O.energy["mesoViscous"] > 0.05 * lost, f"the quadratic dashpot dissipates at chi = {chi}")

# save / load: the material, the contact's pair and a collision halfway
tmp = tempfile.mkdtemp()
g2 = 0.5 * c_crit / v_p
for ext in (".yade.gz", ".xml"):
    s = pair.build(R, 2.0 * v_p, dict(LAW, gammaN2=g2, density=RHO))
    while not (O.interactions.has(0, 1) and O.interactions[0, 1].isReal):
        O.step()
    while O.interactions[0, 1].geom.penetrationDepth <= 0:
        O.step()
    O.run(300, True)
    path = os.path.join(tmp, "mid" + ext)
    O.save(path)
    O.run(3000, True)
    direct = [(tuple(b.state.pos), tuple(b.state.vel)) for b in O.bodies]
    O.load(path)
    check(O.materials[0].gammaN2 == g2, f"{ext}: MesoMat.gammaN2 after O.load", f"{O.materials[0].gammaN2!r} vs {g2!r}")
    check(O.interactions[0, 1].phys.gammaN2 == g2, f"{ext}: the contact's gammaN2 after O.load")
    O.run(3000, True)
    again = [(tuple(b.state.pos), tuple(b.state.vel)) for b in O.bodies]
    check(again == direct, f"{ext}: the collision goes on bit for bit after O.load")

# refused, naming it
try:
    w.MesoMat(gammaN2=-1.0)
    check(False, "gammaN2 = -1 refused")
except ValueError as e:
    check("gammaN2" in str(e), "gammaN2 = -1 refused, naming it", str(e))

finish()
