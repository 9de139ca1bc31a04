"""The agglomerate "tablet" of Luding 2008 / Appendix F of the long paper (run inside ``yade``).

Units are the paper's: 1 mm, 1 us, 1 mg (stiffness 1 = 1e6 N/m, stress 1 = 1e9 Pa). The tablet
is the library's bulk sample (``mesocontact.bulk``) with Appendix F's parameter set
(``bulk.protocol.appendix_f``): primary particles of mean diameter d0 = 0.01 with the full law
(adhesion, friction, rolling, torsion) compacted from a gas by six walls, pressure-sintered at
d0 p_s/kp = 0.02, released to p_r/p_s = 1e-3, and saved:

    from mesostudies.tablet import sample
    info = sample.prepare("released.yade.gz")    # or stages.ensure("released", DIR): reuse
    print(info["released"]["solid_fraction"])

The walls are a smooth, non-adhesive mould until they are glued: with the paper's protocol the two
loading walls get the strongly adhesive material of Luding's tension tests (kc_wall/kp = 20,
mu_wall = 10: 100 times the particles' kc) after sintering; the campaign's chosen preparation
(campaign.PROTOCOL, glue='sinter') gives it to all six walls before sintering. The tests remove
the four lateral walls (uniaxial.make_unconfined). What is particular to the paper lives here: its
material sets, its stresses, and the options of the campaign's factor study.
"""
import math

try:
    from yade import O
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesostudies.tablet.sample needs YADE: run it inside `yade`") from _exc

from mesocontact import scene as _scene
from mesocontact.bulk import protocol as _protocol
from mesocontact.bulk import sample as _bulk
from mesocontact.bulk import sintering as _sintering
# The library's sample tools, under the names the studies use.
from mesocontact.bulk.sample import (  # noqa: F401
    WALLS, energy_scale as _energy_scale, give_material as _give_material, inner_box, kinetic_energy,
    run_until_static, save_atomic, sphere_ids, wall_ids)

D0 = _protocol.APPENDIX_F_D0     # mean primary-particle diameter [mm]
DENSITY = _protocol.TABLE2["density"]  # 2000 kg/m^3 in mg/mm^3
KP = _protocol.APPENDIX_F_KP     # limit stiffness [mg/us^2 = 1e6 N/m]
GAMMA0 = _protocol.TABLE2["gammaN"]  # normal viscous damping [mg/us = kg/s]
SINTER = _protocol.APPENDIX_F_SINTER  # d0 p_s/kp, the paper's sintering stress
SINTER_STRESS = SINTER * KP / D0
RELEASE_RATIO = _protocol.APPENDIX_F_RELEASE  # p_r/p_s
COMPACTION_SPEED, SINTER_SPEED = _protocol.APPENDIX_F_SPEEDS  # largest wall speeds [mm/us]: compaction (~c/10), after
RELEASE_STEPS = 40000            # steps over which the wall stress is lowered from p_s to p_r
# The preparation's options (the factor study of the tested sample, campaigns/tablet/factors.md):
PACKINGS = _protocol.PACKINGS  # the law while the gas is compacted: the full law, or without friction,
#                                rolling, torsion and adhesion (the full law switched on for sintering)
PACKING_RATIO = _protocol.APPENDIX_F_PACKING_RATIO  # the frictionless packing's stress, over p_s
GLUES = _protocol.GLUES  # the walls made adhesive: the two x walls after sintering, all six after
#                          sintering, or all six from the start of sintering (the first protocol's)

# Particle parameter sets (MesoMat keywords, the paper's units): Table 2 of Luding 2008 and the
# long paper's Appendix F, which changes kc, the rolling and torsion limits and their dashpots.
MATERIALS = {"table2": dict(_protocol.TABLE2), "appendixF": dict(_protocol.APPENDIX_F)}

# The scales of every test on a tablet (d0, kp, p_r and the energy scale's stress are the
# paper's whatever the sintering stress): the tests read them from here, not from the scene.
SCALES = _protocol.appendix_f()


def particle_material(material="appendixF", **changes):
    """The particles' MesoMat keywords of parameter set ``material`` ('appendixF': Table 2 of
    Luding 2008 with kc/kp = 0.2, mu_r = mu_o = 0.2, gamma_r/gamma0 = gamma_o/gamma0 = 0.1;
    'table2': Luding's reference set); ``changes`` override."""
    if material not in MATERIALS:
        raise ValueError(f"material = {material!r} is invalid: one of {sorted(MATERIALS)}")
    kw = dict(MATERIALS[material], label="particles")
    kw.update(changes)
    return kw


def background_damping(reference="lab"):
    """Luding's viscous background damping, gamma_b/gamma0 = 4, gamma_br/gamma0 = 1."""
    return _bulk.background_damping(SCALES, reference)


def contact_step(r_min):
    """The tablet campaign's base step: t_c/50 of the stiffest, lightest pair (all springs of the
    law resolved), a fraction of a contact's duration. Not the package's time-step rule, which is
    scene.time_step (a fraction of the stability bound each contact is checked against; this
    step is 0.032 of that bound on the unconfined tablet, campaigns/tablet/timestep.md); the
    campaign keeps this one so that its committed runs stay reproducible, and scales it per test
    (campaign.DT_FACTORS, from the convergence study of campaigns/tablet/timestep.md)."""
    return _bulk.contact_step(SCALES, r_min)


def engines(controller=None, extra=(), reference="lab"):
    """The engine loop of every tablet run: spheres and boxes, meso law, background damping."""
    return _bulk.engines(SCALES, controller, extra, reference)


def stats():
    """bulk.sample.stats with the paper's energy scale."""
    return _bulk.stats(SCALES)


def energy_scale(n):
    """Elastic energy of the sintered sample, the scale of 'static' (bulk.sample.energy_scale at
    the paper's p_s)."""
    return _energy_scale(n, SCALES)


def make_adhesive_walls(ids):
    """The adhesive law of Luding's tension tests (kc_wall/kp = 20, mu_wall = 10) on the walls
    ``ids``, each contact keeping its history (bulk.sample.make_adhesive_walls). Idempotent."""
    _bulk.make_adhesive_walls(ids, SCALES)


def protocol(n=1728, material="appendixF", kc_over_kp=None, rel_std=0.05, seed=1, tol_stress=0.01, tol_ke=1e-4,
             compaction_speed=COMPACTION_SPEED, release_steps=RELEASE_STEPS, packing="full", glue="loading",
             sinter=SINTER, aspect=(1, 1, 1)):
    """The library's Protocol of a tablet: Appendix F's (bulk.protocol.appendix_f) with these
    options. ``sinter`` changes only the sintering stress d0 p_s/kp; the packing's and the
    release's stresses and the energy scale stay the paper's, so that only the sintering depth
    changes."""
    changes = {}
    if kc_over_kp is not None:
        if not (0 <= kc_over_kp < math.inf):
            raise ValueError(f"kc_over_kp = {kc_over_kp} is invalid: must be finite and >= 0")
        changes["kc"] = kc_over_kp * KP
    if not (isinstance(sinter, (int, float)) and math.isfinite(sinter) and sinter > 0):
        raise ValueError(f"sinter = {sinter!r} is invalid: the sintering stress d0 p_s/kp must be a positive number")
    if int(n) != n or n < 8:
        raise ValueError(f"n = {n} is invalid: at least 8 particles")
    mat = particle_material(material, **changes)
    del mat["label"]
    return _protocol.appendix_f(mat, sinter_stress=sinter * KP / D0, n=int(n), rel_std=rel_std, seed=seed,
                                tol_stress=tol_stress, tol_ke=tol_ke, compaction_speed=compaction_speed,
                                release_steps=release_steps, packing=packing, glue=glue, aspect=tuple(aspect),
                                name=material)


def build(n=1728, rel_std=0.05, solid_fraction=0.2, seed=1, material="appendixF", kc_over_kp=None, aspect=(1, 1, 1)):
    """A loose random gas of n spheres in a box of six smooth walls (ids 0-5, spheres after),
    cubic or with sides in the ratios ``aspect`` (x, y, z), particles of parameter set
    ``material`` (kc_over_kp overrides its kc/kp). The Gaussian size distribution is narrow
    (relative std rel_std, cut at 2 sigma) to avoid monodisperse crystallisation."""
    p = protocol(n, material, kc_over_kp, rel_std, seed, aspect=aspect).replace(gas_fraction=solid_fraction)
    return _bulk.build(p)


def set_tensile_stiffness(kc_over_kp):
    """The loaded state with the particles' kc/kp changed (issue E5: does the peak follow the
    contacts' tensile branch?): the "particles" material gets kc = kc_over_kp kp and every
    contact of a sphere adopts it, keeping its history; the loading walls' own kc stays. A
    contact on the tensile branch at this moment changes its force (-kc delta): their number is
    returned with the change. Returns {'kc_over_kp', 'was', 'contacts', 'tensile_fraction'}."""
    if not (isinstance(kc_over_kp, (int, float)) and 0 <= kc_over_kp < math.inf):
        raise ValueError(f"kc_over_kp = {kc_over_kp!r} is invalid: must be a finite number >= 0")
    mat = [m for m in O.materials if m.label == "particles"][0]
    was = mat.kc / KP
    tensile = _scene.branch_fractions().get("tensile", 0.0)
    mat.kc = kc_over_kp * KP
    _give_material(sphere_ids(), mat)
    return {"kc_over_kp": kc_over_kp, "was": was, "contacts": sum(1 for inter in O.interactions if inter.isReal),
            "tensile_fraction": tensile}


LIMITS = {"locked": dict(frictionAngle=math.atan(1e3), muR=1e3, muO=1e3),   # no sliding, rolling or twisting
          "free": dict(frictionAngle=0.0, muR=0.0, muO=0.0)}               # no resistance to them at all


def set_limits(mode):
    """The loaded state with the particles' Coulomb limits of sliding, rolling and torsion changed
    (issue #47, E7: is the early loss of tension the contacts' re-arrangement?): 'locked' (mu,
    muR, muO = 1000: the springs never slip) or 'free' (all 0: no tangential, rolling or torsion
    force); every sphere's contact adopts it keeping its history. Returns {'limits', 'was'}."""
    if mode not in LIMITS:
        raise ValueError(f"limits = {mode!r} is invalid: one of {sorted(LIMITS)}")
    mat = [m for m in O.materials if m.label == "particles"][0]
    was = {k: getattr(mat, k) for k in LIMITS[mode]}
    for k, v in LIMITS[mode].items():
        setattr(mat, k, v)
    _give_material(sphere_ids(), mat)
    return {"limits": mode, "was": was}


def prepare(path, n=1728, material="appendixF", kc_over_kp=None, rel_std=0.05, seed=1, tol_stress=0.01,
            tol_ke=1e-4, compaction_speed=COMPACTION_SPEED, release_steps=RELEASE_STEPS, progress=True,
            packing="full", glue="loading", sinter=SINTER, aspect=(1, 1, 1)):
    """Makes the released tablet (bulk.prepare with protocol(...)): a gas of the particles is
    compacted by the six walls (at up to ``compaction_speed`` [mm/us], without background drag)
    until they carry d0 p_s/kp = 0.02, sintered at that stress with the lab-frame background
    drag until static, glued to the two x walls, released to p_r/p_s = 1e-3 (the goal lowered
    geometrically over ``release_steps`` steps) and relaxed. Saves the released state to
    ``path`` (O.save) and its description to ``path + '.json'`` (both atomically); returns the
    description.

    ``packing='frictionless'`` compacts the gas without friction, rolling, torsion and adhesion
    and lets it come to rest at PACKING_RATIO p_s with the drag, then switches the full law on
    for sintering, each contact keeping its history; ``glue='all'`` makes all six walls
    adhesive after sintering, ``'sinter'`` before it. ``sinter``: the sintering stress d0 p_s/kp
    (the paper's 0.02). ``aspect``: the box's side ratios."""
    p = protocol(n, material, kc_over_kp, rel_std, seed, tol_stress, tol_ke, compaction_speed, release_steps,
                 packing, glue, sinter, aspect)

    def describe(info):
        if sinter != SINTER:
            info["built"]["sinter"] = sinter
    return _sintering.prepare(path, p, progress, describe)
