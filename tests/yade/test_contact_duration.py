# ctest (inside yade): calibrate.contact_duration (the closed-form time with positive overlap,
# used to set k1 from a measured contact time) against YADE pair collisions, below v_p, with and
# without the tensile branch; and from_restitution_and_contact_time's parameters giving the
# asked e and t_c in YADE; params.material_from (e and t_c at one speed with phiF, kc/kp, a
# non-contact fa given, below and beyond the plastic limit) the same, and theory.contact_duration
# there.
import math

from yade import O

from mesocontact import calibrate, pair, params, theory
from harness import check, finish

R, RHO = 1e-3, 2500.0
K1, KP, PHIF = 100.0, 500.0, 0.05


def duration(s):
    r = pair.collide(s, max_contact_times=15, record=True)
    inside = [t for t, d, _, _ in r.trace if d > 0]
    return r, inside[-1] - inside[0]


m_r, a12 = calibrate.geometry(R, RHO)
for kc in (0.0, 100.0):
    for chi in (0.3, 0.45):
        v = theory.impact_velocity_for_chi(chi, K1, KP, PHIF, a12, m_r)
        s = pair.build(R, v, dict(k1=K1, kp=KP, kc=kc, phiF=PHIF), density=RHO)
        r, t_yade = duration(s)
        t_cf = calibrate.contact_duration(chi, (KP - K1) / K1, kc / K1) * math.sqrt(m_r / K1)
        # the recorded overlap changes sign within one step at either end: |error| <= 2 dt
        check(abs(t_yade - t_cf) <= 2 * O.dt,
              f"contact duration kc={kc:g} chi={chi}", f"YADE {t_yade:.6e} s, closed form {t_cf:.6e} s, "
              f"difference {abs(t_yade - t_cf) / t_cf:.1e} relative")

p = calibrate.from_restitution_and_contact_time(0.7, 2e-4, 0.05, 4.0, 1.0, R, RHO)
s = pair.build(R, 0.05, dict(k1=p["k1"], kp=p["kp"], kc=p["kc"], phiF=p["phiF"]), density=RHO)
r, t_yade = duration(s)
check(abs(r.e - 0.7) <= 1e-3, "from_restitution_and_contact_time: e", f"YADE e = {r.e:.6f} (asked 0.7)")
check(abs(t_yade - 2e-4) <= 2 * O.dt, "from_restitution_and_contact_time: t_c",
      f"YADE {t_yade:.6e} s (asked 2e-4 s)")

# params.material_from: what a user asks for, below the plastic limit (0.5 m/s) and beyond it
# (a 1 m/s collision fitted with limit=True), with jump-in adhesion; YADE's e carries the
# non-contact tail's sampling error (the atlas: below 7.1e-4 with fa), t_c the 2 dt of the ends.
for v, e, t_c, limit in ((0.5, 0.6, 6e-4, None), (1.0, 0.75, 5.5e-4, True)):
    mat = params.material_from(R, RHO, v, e, t_c, phiF=0.1, kc_over_kp=0.2, fa=1e-4, kca=100.0, limit=limit)
    law = {k: mat[k] for k in ("k1", "kp", "kc", "phiF", "fa", "kca", "adhesion")}
    s = pair.build(R, v, law, density=RHO)
    r, t_yade = duration(s)
    got = theory.pair_collision(v, law["k1"], law["kp"], law["kc"], 0.1, a12, m_r, 1e-4, 100.0, "jumpIn")
    check(got.plastic_limit == bool(limit), f"material_from at {v} m/s: regime",
          f"k1 = {law['k1']:.4g}, kp = {law['kp']:.4g}, kc = {law['kc']:.4g} N/m, limit reached: {got.plastic_limit}")
    check(abs(r.e - e) <= 1e-3, f"material_from at {v} m/s: e", f"YADE e = {r.e:.6f} (asked {e})")
    check(abs(t_yade - t_c) <= 2 * O.dt, f"material_from at {v} m/s: t_c",
          f"YADE {t_yade:.6e} s (asked {t_c:g} s, dt {O.dt:.2e} s)")
finish()
