# ctest (inside yade): scene.contact_cohesion() is the pull a contact resists from its present state.
# A sphere sticks to a box after a slow impact (jump-in adhesion, damped), is held and pressed in
# by the box to a third of its plastic limit, released to rest; the prediction is read; then the
# box is pulled away slowly: the largest tension of the contact's
# hysteretic plus adhesive force (the viscous part, gamma v, left out) must equal it to the force
# the law changes in one step (kc v dt, the sampling of the peak).
import warnings

from yade import O
from mesocontact import pair, scene
from harness import check, finish

r = 1e-3
mat = dict(k1=1e3, kp=5e3, kc=1e3, phiF=0.1, fa=2e-4, kca=1e3, adhesion="jumpIn", gammaN=0.1)
s = pair.build_wall(r, 0.05, mat, kind="box", steps_per_contact=2000)
O.run(int(150 * s.contact_time / O.dt), True)
ball, box = O.bodies[s.ids[1]], O.bodies[s.ids[0]]
ball.state.blockedDOFs, ball.state.vel, ball.state.angVel = "xyzXYZ", (0, 0, 0), (0, 0, 0)
i = O.interactions[s.ids[0], s.ids[1]]
v = 1e-4
box.state.vel = (0, 0, v)  # press in to a third of the plastic limit's overlap phiF a12 kp/(kp - k1)
while i.geom.penetrationDepth < 0.1 * 2 * r * 5 / 4 / 3:
    O.step()
box.state.vel = (0, 0, 0)
O.step()
c = scene.contact_cohesion()
# A requested pull-off that the contacts do not reach is said; one they reach is not.

for requested, warned in ((10 * c["mean"], True), (0.5 * c["mean"], False)):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scene.contact_cohesion(requested=requested)
    check(bool(caught) == warned, f"requested {requested:.3g} N: {'a warning' if warned else 'no warning'}",
          str(caught[0].message)[:100] if caught else "")

check(c["contacts"] == 1 and c["fa_share"] < 0.5, "one stuck contact, loaded past elastic: its kc term holds most",
      f"delta0 = {i.phys.delta0:.3g} m, fa's share {c['fa_share']:.3f}")
box.state.vel = (0, 0, -v)
most = 0.0
while O.interactions.has(s.ids[0], s.ids[1]) and O.interactions[s.ids[0], s.ids[1]].isReal:
    O.step()
    p = O.interactions[s.ids[0], s.ids[1]].phys if O.interactions.has(s.ids[0], s.ids[1]) else None
    if p is not None and O.interactions[s.ids[0], s.ids[1]].geom.penetrationDepth > 0:
        most = max(most, -(p.hystereticForce + p.adhesiveForce))
tol = mat["kc"] * v * O.dt * 2
check(abs(most - c["mean"]) <= tol, "the pull the contact resisted is contact_cohesion's",
      f"measured {most:.6g} N, predicted {c['mean']:.6g} N (tolerance {tol:.2g} N)")
check(abs(c["fa_share"] - mat["fa"] / c["mean"]) < 1e-12, "fa's share", f"{c['fa_share']:.3f}")

finish()
