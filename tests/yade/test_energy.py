# ctest (inside yade): with O.trackEnergy, kinetic + stored + dissipated energy stays constant to
# 1e-4 of the initial kinetic energy at every step of a collision, with every mechanism of the
# normal law on, and the force parts add up to `normalForce`; the hysteretic dissipation of a
# rebound equals the closed form E_i (1 - e^2).

from yade import O
from mesocontact import pair, params, theory
from harness import failures, finish

r = 1.1e-3
m_r = params.sphere_mass(r, 2000) / 2
fa = params.fa_from_alpha(0.42, 100, m_r, 0.01)
base = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1)
cases = [
    ("fa=0, elastic-plastic rebound", dict(base), 0.34, None),
    ("jumpIn + viscous, sticking", dict(base, fa=fa, kca=100.0, adhesion="jumpIn", gammaN=5e-3), 1.0, None),
    ("reversible + viscous, rebound", dict(base, fa=fa, kca=100.0, adhesion="reversible", gammaN=2e-3), 2.0, None),
    ("sqrt, unequal radii, jumpIn", dict(base, fa=fa, kca=50.0, adhesion="jumpIn", k2Interpolation="sqrt"), 1.5, 2e-3),
]
for label, mat, zeta, r2 in cases:
    mr = params.reduced_mass(params.sphere_mass(r, 2000), params.sphere_mass(r2 or r, 2000))
    v = zeta * theory.plastic_limit_velocity(100, 500, 0.1, params.reduced_radius(r, r2 or r), mr, mat.get("fa", 0.0))
    s = pair.build(r, v, mat, radius2=r2, track_energy=True)
    O.step()
    e0 = O.energy.total()
    ek0 = 0.5 * s.m_r * v * v
    worst = split = 0.0
    n = int(12 * s.contact_time / O.dt)
    for _ in range(n):
        O.step()
        worst = max(worst, abs(O.energy.total() - e0) / ek0)
        if O.interactions.has(*s.ids) and O.interactions[s.ids].isReal:  # the parts add up to the force applied
            i = O.interactions[s.ids]
            parts = i.phys.hystereticForce + i.phys.adhesiveForce + i.phys.viscousForce
            split = max(split, abs(i.phys.normalForce.dot(i.geom.normal) - parts) / (s.m_r * v / s.contact_time))
    parts = {k: O.energy[k] / ek0 for k in O.energy.keys()}
    ok = worst <= 1e-4 and abs(e0 - ek0) / ek0 < 1e-6 and split <= 1e-12
    line = (f"{label:32s} max |E_total - E_0|/E_kin,0 = {worst:.2e}; force parts vs normalForce {split:.1e}; "
            "final shares: " + ", ".join(f"{k}={val:.4f}" for k, val in sorted(parts.items()) if val != 0))
    if label.startswith("fa=0"):  # rebound: all the lost kinetic energy went into the hysteresis
        e_th = theory.pair_collision(v, 100, 500, 100, 0.1, s.a12, s.m_r).e
        plastic_err = abs(parts["mesoPlastic"] - (1 - e_th ** 2)) / (1 - e_th ** 2)
        ok = ok and plastic_err <= 1e-3
        line += f"; plastic vs E_i(1-e^2): rel. error {plastic_err:.1e}"
    if "viscous" in label and not parts.get("mesoViscous", 0) > 0:
        ok = False
        line += "; no viscous dissipation booked"
    print(("ok   " if ok else "FAIL ") + line, flush=True)
    if not ok:
        failures.append(label)
# All mechanisms: oblique, spinning sphere-sphere (ScGeom6D) and sphere-box collisions with
# sliding, rolling and torsion springs, dashpots and Coulomb limits, adhesion, viscosity and
# viscous background damping.
from yade import wrapper as wr  # noqa: E402

full = dict(base, fa=fa, kca=100.0, adhesion="jumpIn", gammaN=2e-3, kt=40.0, gammaT=1e-3, frictionAngle=0.3,
            kr=20.0, gammaR=5e-4, muR=0.1, ko=20.0, gammaO=5e-4, muO=0.1, phiD=0.8)
for label, wall, reference in (("all mechanisms, sphere-sphere 6D", False, "lab"),
                               ("all mechanisms, sphere-box 6D", True, "lab"),
                               ("sphere-sphere 6D, drag vs contacts", False, "contacts"),
                               ("sphere-box 6D, drag vs contacts", True, "contacts")):
    v = 0.08
    if wall:
        s = pair.build_wall(r, v, full, kind="box", six_d=True, tangential_velocity=(0.05, 0.02, 0), spin=(30, -50, 80),
                            track_energy=True)
    else:
        s = pair.build(r, v, full, track_energy=True)
        f = O.engines[2].geomDispatcher.functors[0]
        O.engines[2].geomDispatcher.functors = [
            wr.Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=f.interactionDetectionFactor)]
        O.bodies[s.ids[0]].state.vel += (0, 0.04, 0.01)  # oblique
        O.bodies[s.ids[0]].state.angVel = (40, 0, -60)
        O.bodies[s.ids[1]].state.angVel = (0, 70, 20)
    O.engines = O.engines[:-1] + [wr.MesoBackgroundDamping(gammaB=1e-4, gammaBR=1e-4,
                                                           reference=reference)] + O.engines[-1:]
    O.step()
    e0 = O.energy.total()
    worst = 0.0
    for _ in range(int(12 * s.contact_time / O.dt)):
        O.step()
        worst = max(worst, abs(O.energy.total() - e0) / e0)
    parts = {k: O.energy[k] / e0 for k in O.energy.keys()}
    ok = worst <= 1e-4 and all(parts.get(k, 0) > 0
                               for k in ("mesoSliding", "mesoRolling", "mesoTorsion", "mesoBackground"))
    print(("ok   " if ok else "FAIL ") + f"{label:32s} max |E_total - E_0|/E_0 = {worst:.2e}; final shares: "
          + ", ".join(f"{k}={val:.4f}" for k, val in sorted(parts.items()) if val != 0), flush=True)
    if not ok:
        failures.append(label)
finish()
