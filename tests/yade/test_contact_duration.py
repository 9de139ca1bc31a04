# ctest (inside yade): calibrate.contact_duration (the closed-form time with positive overlap,
# used to set k1 from a measured contact time) against YADE pair collisions, below v_p, with and
# without the tensile branch; and from_restitution_and_contact_time's parameters giving the
# asked e and t_c in YADE.
import math

from yade import O

from mesocontact import calibrate, pair, theory
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
finish()
