"""A uni-axial test's records as a CSV and a picture (bulk.uniaxial.Test.write_csv, .plot)."""
from .. import outputs as _outputs
from ..scene_names import BRANCHES


def write_csv(test, path):
    """iter, Dx, F_over_kp_d0, L (the length measured, in the scene's units), wall_work, energy_change
    (empty before track_energy()) and one column per branch of the law, a row per record."""
    energy = {e[0]: e[1:] for e in test.energy}
    branches = {b[0]: b[2:] for b in test.branches}
    lines = ["iter,Dx,F_over_kp_d0,L,wall_work,energy_change," + ",".join(BRANCHES)]
    for (it, dx, f), length in zip(test.rows, test.lengths):
        e = [repr(x) for x in energy[it]] if it in energy else ["", ""]
        b = [repr(x) for x in branches.get(it, ())]
        lines.append(",".join([str(int(it)), repr(dx), repr(f), repr(length)] + e + b))
    _outputs.write_atomic(path, "\n".join(lines) + "\n")


def plot(test, path, title=""):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    a.plot([r[1] for r in test.rows], [r[2] for r in test.rows], lw=1)
    a.axhline(0, color="0.6", lw=0.5)
    a.set_xlabel("Dx = (L - L0)/d0  (> 0: longer)")
    a.set_ylabel("F/(kp d0)  (> 0: compression)")
    a.set_title(title, fontsize=9)
    x = [r[0] for r in test.branches]
    for k, name in enumerate(BRANCHES):
        y = [r[2 + k] for r in test.branches]
        if any(y):
            b.plot(x, y, lw=1, label=name)
    b.set_xlabel("step")
    b.set_ylabel("fraction of the contacts")
    b.legend(fontsize=7)
    fig.tight_layout()
    _outputs.savefig_atomic(fig, path, dpi=110)
    plt.close(fig)
