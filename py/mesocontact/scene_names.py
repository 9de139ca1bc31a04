"""Names shared by the YADE side (scene) and plain-Python readers of its files (no YADE here)."""

# The branches of MesoPhys.branch, in the order of MesoPhys.branchIndex.
BRANCHES = ("new", "apart", "nonContact", "loading", "limit", "unloading", "tensile")
