# ctest (inside yade): the tablet's factor table from made-up files whose answers are worked by
# hand: the weakest plane at the peak and at Dx = 0.2 and 0.81 (where the crack runs), each
# criterion's ✓/✗ (a crack 1.1 d0 from a wall is not in the bulk), and the realizations' summary
# (the values, their mean and sample standard deviation).
#
# The tablet's factor table (campaigns/tablet/factors/factors.md) from made-up
# files, so that every criterion's answer and every summary is known by hand: two realizations
# (seeds 1 and 2) of one preparation, L0 = 0.1155 (+0.43 %), the weakest plane 4.125 d0 from the
# left wall at the peak; at Dx = 0.81 the crack plane 5.125 d0 from the left wall (seed 1) or
# 1.125 d0 (seed 2); first gap 1.0 and 1.2, last chain 7 and 9.
import json
import os
import shutil
import tempfile

from mesostudies.tablet import campaign, stages
import harness
from harness import check, finish

fdir = tempfile.mkdtemp(prefix="factor-table-")
stage = {"n": 1728, "solid_fraction": 0.6, "coordination": 5.0, "rattlers": 3, "side": [0.1155, 0.115, 0.115]}


def profile(weakest, length):
    prof = {"x": [0.125 + 0.25 * k for k in range(46)], "count": [100] * 46, "length_d0": length}
    prof["count"][weakest] = 50
    prof["mean"] = sum(prof["count"]) / 46
    return prof


for seed, crack, gap, last in ((1, 20, 1.0, 7.0), (2, 4, 1.2, 9.0)):
    prep = campaign.factor_dir(fdir, "frictionless", "loading", seed=seed)
    os.makedirs(os.path.join(prep, "pull-contacts"))
    json.dump({"built": {"packing": "frictionless", "glue": "loading", "seed": seed}, "sintered": stage,
               "released": stage, "unconfined": {"stats": stage}}, open(stages.path("unconfined", prep) + ".json", "w"))
    at_peak = profile(16, 11.55)  # 4.125 d0 from the left face
    json.dump({"drag": "contacts", "L0": 0.1155, "max_tension": -0.05, "max_tension_Dx": 0.2,
               "planes_at_start": at_peak, "planes_at_peak": dict(at_peak, Dx=0.0),
               "planes_at_marks": {"0.2": dict(profile(crack, 11.75), Dx=0.2),
                                   "0.81": dict(profile(crack, 12.36), Dx=0.81)},
               "first_gap_Dx_by_area": {"0.5": 0.8, "1": gap, "2": 1.5},
               "last_contact_Dx": last, "mean_force_after_last_contact": 0.0, "wall_clock_s": 1.0},
              open(os.path.join(prep, "pull-contacts", "pull-contacts.json"), "w"))

rows = sorted(campaign.factor_table(fdir), key=lambda r: r["seed"])
md = open(os.path.join(fdir, "factors", "factors.md")).read()
check(rows[0]["weakest_at_peak"] == {"count": 50, "from_left_d0": 4.125, "from_right_d0": 11.55 - 4.125},
      "factor table: the weakest plane at the peak", str(rows[0]["weakest_at_peak"]))
check(rows[0]["weakest_at_marks"]["0.81"] == {"count": 50, "from_left_d0": 5.125, "from_right_d0": 12.36 - 5.125}
      and rows[1]["weakest_at_marks"]["0.2"]["from_left_d0"] == 1.125,
      "factor table: the weakest plane at the marks 0.2 and 0.81", str(rows[0]["weakest_at_marks"]))
check("frictionless, loading, radii std 0.05, seed 1, contacts: L0 ✓, bulk rupture ✓, crack in the bulk ✓, "
      "first gap ✓, last chain ✓ (L0 +0.43 %)" in md, "factor table: seed 1 meets every criterion")
check("seed 2, contacts: L0 ✓, bulk rupture ✓, crack in the bulk ✗, first gap ✓, last chain ✓" in md,
      "factor table: seed 2's crack at 1.125 d0 from a wall is not in the bulk")
# the realizations' summary: mean and sample sd of (7, 9), (1.0, 1.2), (5.125, 1.125), worked by hand
for line in ("- last chain Dx: 7.00, 9.00: mean 8.00, sd 1.41",
             "- first gap Dx (1 d0^2): 1.00, 1.20: mean 1.10, sd 0.14",
             "- weakest plane at Dx = 0.81 from the nearer wall [d0]: 5.1, 1.1: mean 3.1, sd 2.8",
             "- L0 against 0.115 [%]: 0.43, 0.43: mean 0.43, sd 0.00"):
    check(line in md, f"factor table: realizations summary {line!r}")
check("seeds 1, 2" in md, "factor table: the realizations are grouped (seeds 1, 2)")

# The committed table (campaigns/tablet/factors/factors.md) is what the script writes from the committed files.
docs = os.path.join(os.path.dirname(os.path.abspath(harness.__file__)), "..", "..", "campaigns", "tablet", "factors")
copy = tempfile.mkdtemp(prefix="factor-docs-")
shutil.copytree(docs, os.path.join(copy, "factors"))
campaign.factor_table(copy)
check(open(os.path.join(copy, "factors", "factors.md")).read() == open(os.path.join(docs, "factors.md")).read(),
      "campaigns/tablet/factors/factors.md is generated: studies/scripts/tablet.py factors --out "
      "campaigns/tablet --table")
finish()
