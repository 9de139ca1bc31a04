# ctest (inside yade): the adhesion modes and the law's branches, each a table in the C++ core
# (MESO_ADHESION_MODES, MESO_BRANCHES), against the names the Python side writes and reads
# (theory.ADHESION_MODES, scene_names.BRANCHES) and the mixing order the documentation states
# ('none' < 'jumpIn' < 'reversible': a pair takes the weaker mode), written out here.
import itertools

from yade import wrapper as w
from mesocontact import scene_names, theory
from harness import check, finish

modes = w.MesoMat.adhesionModes()
check(modes == tuple(theory.ADHESION_MODES), f"theory's adhesion modes are the C++ table's {modes}")
check(w.MesoPhys.branchNames() == tuple(scene_names.BRANCHES),
      f"scene_names.BRANCHES are the C++ branches {w.MesoPhys.branchNames()}")

try:
    w.MesoMat(adhesion="glue")
    check(False, "an unknown mode is refused")
except ValueError as e:
    listed = [m for m in modes if f"'{m}'" in str(e)]
    check(str(e).startswith("adhesion") and listed == list(modes),
          f"an unknown mode is refused, every mode listed: {e}")

doc = w.MesoMat.adhesion.__doc__ or ""
check(all(f"'{m}'" in doc for m in modes), "MesoMat.adhesion's doc names every mode")

WEAKER_FIRST = ("none", "jumpIn", "reversible")
ip2 = w.Ip2_MesoMat_MesoMat_MesoPhys()
for a, b in itertools.product(modes, repeat=2):
    mats = [w.MesoMat(adhesion=m, fa=1e-6 if m != "none" else 0.0, kca=1.0) for m in (a, b)]
    got = ip2.mixedParameters(mats[0], mats[1])["adhesion"]
    want = min(a, b, key=WEAKER_FIRST.index)
    check(got == want, f"{a} with {b}: the pair takes {got} (the weaker: {want})")

finish()
