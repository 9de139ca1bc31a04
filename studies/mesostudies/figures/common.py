"""What the papers' pair figures share: the parameters of Figs. 5-8, the note under each figure,
its CSV and PNG (written whole), progress lines (inside ``yade``)."""
import csv
import io
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from mesocontact import outputs, params  # noqa: E402

# Fig. 5-8 parameters (docs/model.md §9): k1 = 1e2, kp = 5e2, kc = 1e2 N/m, radius 1.1 mm, 2000 kg/m3.
PAPER = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1)
RADIUS, DENSITY = 1.1e-3, 2000.0


def pair_reduced_mass():
    return params.sphere_mass(RADIUS, DENSITY) / 2


PARAM_NOTE = (f"k1 = {PAPER['k1']:g}, kp = {PAPER['kp']:g}, kc = {PAPER['kc']:g} N/m, a = {RADIUS * 1e3:g} mm, "
              f"ρ = {DENSITY:g} kg/m³, γ0 = 0")


def fig_note(fig, text, fontsize=7.5):
    """Parameters under the figure (a box inside a panel would hide data), wrapped at commas to the
    figure's width; _note_rect(fig) then keeps the panels above it."""
    width_pt, height_pt = fig.get_size_inches() * 72
    per_line = max(20, int(0.92 * width_pt / (0.52 * fontsize)))  # about 0.52 em per character
    lines, line = [], ""
    for part in text.split(", "):
        candidate = part if not line else line + ", " + part
        if len(candidate) > per_line and line:
            lines.append(line + ",")
            line = part
        else:
            line = candidate
    lines.append(line)
    fig.text(0.5, 0.005, "\n".join(lines), ha="center", va="bottom", fontsize=fontsize, color="0.25", linespacing=1.25)
    fig._meso_note_bottom = (len(lines) * 1.25 * fontsize + 4) / height_pt


def _note_rect(fig):
    """tight_layout's rect that leaves the note under the panels free."""
    return (0, getattr(fig, "_meso_note_bottom", 0.03), 1, 1)


def save_figure(fig, outdir, stem):
    """Lays the figure out above its note, writes <outdir>/<stem>.png (atomically) and closes it."""
    fig.tight_layout(rect=_note_rect(fig))
    outputs.savefig_atomic(fig, os.path.join(outdir, stem + ".png"), dpi=150)
    plt.close(fig)


def write_csv(path, header, rows):
    text = io.StringIO(newline="")
    w = csv.writer(text)
    w.writerow(header)
    w.writerows(rows)
    outputs.write_atomic(path, text.getvalue())  # a stopped job leaves the old file or the new one


def print_progress(tag, i, n, t0):
    print(f"[{tag}] {i}/{n} collisions, {time.time() - t0:.1f} s", flush=True)
