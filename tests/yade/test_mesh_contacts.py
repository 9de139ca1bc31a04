# ctest (inside yade): one contact per mesh surface (issue #50 item 4). A sphere with reversible
# adhesion falls onto a floor of two coplanar facets (the square split along its diagonal, as
# geom.facetBox makes it) over the diagonal, over one facet near it, and over the outer corner the
# two share; the same fall onto one large facet is the reference. On the floor of two facets the
# sphere has one contact at every step and rebounds as from the large facet (same pull-in, same
# stiffness; to the rounding of a nearest point computed on an edge instead of the face). A sphere
# in a valley of two facets at 90 degrees keeps a contact on each face.
import math

from yade import O, utils
from yade import wrapper as w
from mesocontact import scene
from harness import check, finish

R, RHO, V0 = 1e-3, 2000.0, 0.02
MAT = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=1e-5, kca=50.0, adhesion="reversible", density=RHO)
L = 5 * R  # half the floor's side


def fall(facets, start, direction=(0, 0, -1)):
    """The sphere from ``start`` at V0 along ``direction`` onto ``facets`` (vertex triples): the
    most facet contacts it had at one step, its velocity along -direction after the rebound (or
    None, stuck), and the contacts at the deepest point."""
    scene.reset()
    O.materials.append(w.MesoMat(**MAT))
    ids = [O.bodies.append(utils.facet(v, fixed=True, material=0)) for v in facets]
    ball = O.bodies.append(utils.sphere(start, R, material=0))
    b = O.bodies[ball]
    b.state.vel = tuple(V0 * d for d in direction)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Facet_Aabb()], verletDist=0),
                 w.InteractionLoop([w.Ig2_Facet_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    scene.set_detection()
    O.dt = 2e-8
    most = 0
    for _ in range(200000):
        O.step()
        n = sum(1 for i in ids if O.interactions.has(i, ball) and O.interactions[i, ball].isReal)
        most = max(most, n)
        if n == 0 and O.iter > 10 and b.state.vel.dot(direction) < 0:
            break
    v_out = -b.state.vel.dot(direction) if b.state.vel.dot(direction) < 0 else None
    return most, v_out


floor = [[(-L, -L, 0), (L, -L, 0), (L, L, 0)], [(-L, -L, 0), (L, L, 0), (-L, L, 0)]]  # the diagonal (-L,-L)-(L,L)
large = [[(-4 * L, -4 * L, 0), (4 * L, -4 * L, 0), (0, 4 * L, 0)]]
gap = 1.5 * MAT["fa"] / MAT["kca"]

for where, xy in (("over the diagonal", (0.0, 0.0)),
                  ("over one facet, 0.05 R from the diagonal", (0.05 * R / math.sqrt(2), -0.05 * R / math.sqrt(2))),
                  ("over the shared corner (-L, -L)", (-L + 0.2 * R, -L + 0.25 * R))):
    start = (xy[0], xy[1], R + gap)
    most, v = fall(floor, start)
    most_ref, v_ref = fall(large, start)
    check(most_ref == 1, f"{where}: the large facet holds one contact", str(most_ref))
    check(most == 1, f"{where}: two coplanar facets hold one contact at every step", f"at most {most}")
    # Rounding only: the same overlap computed from a nearest point on an edge instead of the face.
    check(v is not None and v_ref is not None and abs(v - v_ref) <= 1e-9 * V0,
          f"{where}: the rebound equals the large facet's", f"v = {v!r}, large facet {v_ref!r} m/s")

# A valley: two faces at 90 degrees along the x axis, the sphere coming down the bisector.
valley = [[(-L, 0, 0), (L, 0, 0), (0, -L, L)], [(-L, 0, 0), (L, 0, 0), (0, L, L)]]
s = 1 / math.sqrt(2)
most, v = fall(valley, (0.0, 0.0, (R + gap) / s), direction=(0, 0, -1))
check(most == 2, "a valley of two facets keeps a contact on each face", f"at most {most}")
finish()
