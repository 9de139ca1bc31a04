# ctest (inside yade): a sphere held on an adhesive wall by kc alone (fa = 0: at rest the
# hysteretic force is zero, the Coulomb limit is mu kc delta) or by kc and fa resists a slowly
# growing tangential pull up to mu_s (f_n + kc delta) and slides beyond it; under a constant pull
# beyond the limit it accelerates at (F - mu_d (f_n + kc delta))/m. Rotation is blocked so the
# sphere slides (a free sphere would roll).
import math

from yade import O, wrapper as w
from mesocontact import pair, params, theory
from harness import check, failures, finish

RAMP = {}


def ramp_tick():
    st = RAMP
    F = st["rate"] * (O.time - st["t0"])
    st["pull"].force = (F, 0, 0)
    ft = st["ph"].shearForce.norm()
    if ft > st["peak"]:
        st.update(peak=ft, peak_force=F,
                  peak_level=st["ph"].coulombLevel)
    if st["ball"].state.vel[0] > 20 * st["creep"]:
        st["slipped"] = True
        O.stopAtIter = O.iter + 1  # not O.pause() from inside the loop (see pair._watch)


r = 1e-3
m = params.sphere_mass(r, 2000)
base = dict(k1=1e3, kp=5e3, kc=1e3, phiF=0.1, gammaN=0.1, kt=400.0, gammaT=2e-2, frictionAngle=math.atan(0.5), phiD=0.8)
cases = [("held by kc alone (fa = 0)", dict(base)),
         ("held by kc and fa (jumpIn)", dict(base, fa=2e-3, kca=1e3, adhesion="jumpIn"))]
for label, mat in cases:
    # 1. a sticking impact, then rest (viscous)
    v_p = theory.plastic_limit_velocity(1e3, 5e3, 0.1, 2 * r, m, mat.get("fa", 0.0))
    s = pair.build_wall(r, 0.9 * v_p, mat, kind="box", steps_per_contact=200)
    ball = O.bodies[s.ids[1]]
    O.run(int(150 * s.contact_time / O.dt), True)
    i = O.interactions[s.ids[0], s.ids[1]]
    ph = i.phys
    # The Coulomb level from its definition, once, against the law's own (which the other tests read).
    level = ph.hystereticForce + ph.viscousForce + ph.kc * i.geom.penetrationDepth
    check(abs(ph.coulombLevel - level) <= 1e-15 * abs(level), f"{label}: MesoPhys.coulombLevel",
          f"{ph.coulombLevel:.17e} N against f_h + f_v + kc delta = {level:.17e} N")
    if not (ball.state.vel.norm() < 1e-8 and level > 0):
        failures.append(f"{label}: not at rest in contact (v = {ball.state.vel.norm():.2e}, level = {level:.3e})")
        continue
    mu_s, mu_d = ph.muS, 0.8 * ph.muS
    # 2. slow ramp of a pull along x (updated every 20 steps inside YADE's loop) until it slips
    ball.state.blockedDOFs = "XYZ"
    pull = w.ForceEngine(ids=[s.ids[1]], force=(0, 0, 0))
    f_lim = mu_s * level
    ramp_time = 400000 * O.dt
    elastic_rate = 1.5 * f_lim / ramp_time / ph.kt  # creep of a stuck contact: (dF/dt)/kt
    RAMP.update(t0=O.time, peak=0.0, peak_force=0.0, peak_level=level, slipped=False, ball=ball, ph=ph, i=i,
                pull=pull, rate=1.5 * f_lim / ramp_time, creep=elastic_rate)
    ticker = w.PyRunner(iterPeriod=20, command="ramp_tick()")
    O.engines = O.engines[:-1] + [pull] + O.engines[-1:] + [ticker]
    O.stopAtIter = O.iter + 500000
    O.run()
    O.wait()
    O.engines = [e for e in O.engines if e is not ticker]
    peak, peak_level = RAMP["peak"], RAMP["peak_level"]
    stat_err = abs(peak - mu_s * peak_level) / (mu_s * peak_level)
    onset_err = abs(RAMP["peak_force"] - mu_s * peak_level) / (mu_s * peak_level) if RAMP["slipped"] else math.inf
    # 3. constant pull 1.5x the static limit: acceleration (F - mu_d level)/m
    F = 1.5 * f_lim
    pull.force = (F, 0, 0)
    O.run(200, True)
    t0, v0 = O.time, ball.state.vel[0]
    O.run(2000, True)
    acc = (ball.state.vel[0] - v0) / (O.time - t0)
    lv = ph.coulombLevel
    acc_th = (F - mu_d * lv) / m
    acc_err = abs(acc - acc_th) / acc_th
    dyn_err = abs(ph.shearForce.norm() - mu_d * lv) / (mu_d * lv)
    ok = stat_err <= 1e-3 and onset_err <= 1e-3 and acc_err <= 1e-3 and dyn_err <= 1e-3
    check(ok, label, f"level f_n + kc delta = {level:.4e} N (kc delta = {ph.kc * i.geom.penetrationDepth:.4e}); "
          f"peak |f_t| / (mu_s level) - 1 = {stat_err:.1e}; applied pull at the peak / (mu_s level) - "
          f"1 = {onset_err:.1e}; sliding |f_t| / (mu_d level) - 1 = {dyn_err:.1e}; acceleration rel. "
          f"error = {acc_err:.1e}")
finish()
