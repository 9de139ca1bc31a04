# ctest (inside yade): mesocontact.scene.set_detection makes a hand-built scene see reversible
# adhesion before contact. Two spheres approach across the pull-in range with YADE's default
# detection: no force acts until they touch (the Ip2 warns) and e misses the closed form; after
# set_detection the same scene meets it (|de| <= 1e-3, the pair driver's own tolerance).
from yade import O, utils
from yade import wrapper as w
from mesocontact import params, scene, theory
from harness import check, finish

R, RHO, V = 1e-3, 2000.0, 0.004
MAT = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=1e-5, kca=50.0, adhesion="reversible", density=RHO)
m_r = params.sphere_mass(R, RHO) / 2
e_theory = theory.pair_collision(V, 100.0, 500.0, 100.0, 0.1, R, m_r, fa=1e-5, kca=50.0, adhesion="reversible").e


def collide(detect):
    scene.reset()
    O.materials.append(w.MesoMat(**MAT))
    gap = 1.5 * MAT["fa"] / MAT["kca"]  # outside the range of the non-contact force
    b1, b2 = utils.sphere((0, 0, 0), R, material=0), utils.sphere((2 * R + gap, 0, 0), R, material=0)
    O.bodies.append([b1, b2])
    b1.state.vel, b2.state.vel = (V / 2, 0, 0), (-V / 2, 0, 0)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()], verletDist=0),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    factor = scene.set_detection() if detect else 1.0
    O.dt = params.contact_time(500.0, m_r) / 2000
    O.run(int(3 * params.contact_time(100.0, m_r) / O.dt + gap / V / O.dt), True)
    return (b2.state.vel - b1.state.vel)[0] / V, factor


e_default, _ = collide(False)
e_set, factor = collide(True)
RANGE = MAT["fa"] / MAT["kca"]
check(abs(scene.adhesion_range() - RANGE) < 1e-12 * RANGE, "adhesion_range = fa/kca of the scene's material", f"{scene.adhesion_range():.3e}")
check(abs(factor - (1 + 1.2 * RANGE / R)) < 1e-12, "set_detection: factor 1 + 1.2 range/a_min", f"{factor}")
check(abs(e_default - e_theory) > 1e-3, "default detection misses the pull-in (e off the closed form)",
      f"e = {e_default:.6f}, theory {e_theory:.6f}")
check(abs(e_set - e_theory) <= 1e-3, "after set_detection e meets the closed form", f"e = {e_set:.6f}, theory {e_theory:.6f}")
scene.reset()
O.materials.append(w.MesoMat(k1=100.0, kp=500.0, density=RHO))
O.bodies.append(utils.sphere((0, 0, 0), R, material=0))
O.engines = [w.InsertionSortCollider([w.Bo1_Sphere_Aabb()])]
check(scene.set_detection() == 1.0 and O.engines[0].boundDispatcher.functors[0].aabbEnlargeFactor <= 1.0,
      "no adhesion: engines left alone")
try:
    scene.set_detection(margin=0.5)
    check(False, "margin < 1 refused")
except ValueError as e:
    check("margin" in str(e), "margin < 1 refused, naming it", str(e))
finish()
