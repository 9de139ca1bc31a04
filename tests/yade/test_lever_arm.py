# ctest (inside yade): the torques of one step of two unequal spheres pressed together deeply
# (delta/a ~ 0.06) and spinning, against the arms written out here: the sliding force acts at
# the contact point, arm_i = a_i - delta/2 from each centre; rolling and torsion act through
# a' = arm1 arm2/(arm1 + arm2) ('reduced') or twice that ('a12'). At this overlap a wrong arm
# (e.g. a - 0.4 delta) changes the torques by ~0.5 %, far above the 1e-12 compared here
# (the earlier tests' 1e-3 tolerances could not see delta/a ~ 4e-4).

from yade import O, utils, Vector3
from yade import wrapper as w
from harness import check, finish

a1, a2 = 1.0e-3, 0.7e-3
delta = 0.06 * a2
for lever in ("reduced", "a12"):
    O.reset()
    mat = O.materials.append(w.MesoMat(k1=100.0, kp=500.0, kc=50.0, kt=80.0, gammaT=1e-3, frictionAngle=0.5, kr=40.0,
                                       gammaR=1e-3, muR=0.5, ko=30.0, gammaO=1e-3, muO=0.5, density=2000.0))
    O.bodies.append([utils.sphere((0, 0, 0), a1, material=mat),
                     utils.sphere((a1 + a2 - delta, 0, 0), a2, material=mat)])
    O.bodies[0].state.angVel = Vector3(0.3, 2.0, -1.1)
    O.bodies[1].state.angVel = Vector3(-0.7, 0.4, 1.5)
    O.bodies[1].state.vel = Vector3(0, 0.01, 0.004)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D()], [w.Ip2_MesoMat_MesoMat_MesoPhys(leverArm=lever)],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    O.dt = 1e-7
    O.step()  # the contact is made
    O.engines = O.engines[:3]  # forces of one more step, bodies not moved: they stay readable
    O.step()
    i = O.interactions[0, 1]
    d = i.geom.penetrationDepth
    n = i.geom.normal
    arm1, arm2 = a1 - d / 2, a2 - d / 2
    lever_arm = arm1 * arm2 / (arm1 + arm2) * (2 if lever == "a12" else 1)
    fT = -i.phys.shearForce  # on body 1
    quasi = lever_arm * (i.phys.torsionForce * n - n.cross(i.phys.rollingForce))
    expect1 = arm1 * n.cross(fT) + quasi
    expect2 = arm2 * n.cross(fT) - quasi
    got1, got2 = O.forces.t(0), O.forces.t(1)
    scale = max(expect1.norm(), expect2.norm())
    err = max((got1 - expect1).norm(), (got2 - expect2).norm()) / scale
    parts = fT.norm() > 0 and i.phys.rollingForce.norm() > 0 and abs(i.phys.torsionForce) > 0
    ok = parts and err <= 1e-12 and abs(i.phys.leverArm / lever_arm - 1) <= 1e-14 and abs(d / delta - 1) < 0.01
    check(ok, f"leverArm '{lever}'",
          f"delta/a2 = {d / a2:.4f}, torques against arm_i = a_i - delta/2, a' = {lever_arm:.6e}: "
          f"rel. error {err:.1e} (|T1| {got1.norm():.3e}); sliding {fT.norm():.2e}, rolling "
          f"{i.phys.rollingForce.norm():.2e}, torsion {abs(i.phys.torsionForce):.2e}")
finish()
