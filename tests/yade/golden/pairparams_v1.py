# Writes pairparams_v1.yade.gz and its .json: a saved contact and materials of the layout before
# gammaN2 (PairParams version 1 with phiD, MesoMat version 0). Run once with the plugin of commit
# add2ac8 (a layout of that kind); test_param_table.py loads the file with the present one:
#   yade-meso -n -x tests/yade/golden/pairparams_v1.py tests/yade/golden
import json
import os
import sys

sys.path.insert(0, sys.argv[-1])  # the golden folder, where pairparams_v0.py lies
from yade import O  # noqa: E402
from pairparams_v0 import A, B, NAMES, contact, recorded  # noqa: E402

if __name__ == "__main__":
    out = sys.argv[-1]
    state = recorded(contact(A, B, 300).phys, NAMES[:5] + ["phiD"] + NAMES[5:])
    O.save(os.path.join(out, "pairparams_v1.yade.gz"))
    with open(os.path.join(out, "pairparams_v1.json"), "w") as f:
        json.dump({"written_by": "add2ac8", "contact": state,
                   "materials": [{k: getattr(m, k) for k in A if k != "density"} for m in O.materials]}, f, indent=1)
    print("wrote", out)
