# ctest (inside yade): an adhesive wall pulls a sphere along when it moves away.

from yade import O
from mesocontact import pair
from harness import failures, finish

r = 1e-3
# An adhesive wall pulls a sphere: settle on a box, then move the box down slowly.
mat = dict(k1=1e3, kp=5e3, kc=1e3, phiF=0.1, fa=2e-3, kca=1e3, adhesion="jumpIn", gammaN=0.1)
s = pair.build_wall(r, 0.05, mat, kind="box", steps_per_contact=200)
O.run(int(150 * s.contact_time / O.dt), True)
wall, ball = O.bodies[s.ids[0]].state, O.bodies[s.ids[1]].state
wall.vel = (0, 0, -0.01)
O.run(int(50 * s.contact_time / O.dt), True)
ok = O.interactions.has(s.ids[0], s.ids[1]) and abs(ball.vel[2] - (-0.01)) < 1e-4
print(("ok   " if ok else "FAIL ")
      + f"adhesive wall pulling: sphere velocity {ball.vel[2]:.5f} m/s following the wall's -0.01 m/s")
if not ok:
    failures.append("wall pull")
finish()
