# Redraws a campaign folder's figures from its committed data (nothing is run): Figs. 16 and 18
# (and a test variant's, <prefix>fig16.json) from their JSON and the runs' CSVs beside them, Fig. 17
# from fig17.json and fig17.csv, a strain profile from profile.json and profile-slabs.csv. For a change of the plots
# only; the folder's manifest is then refreshed with
#   python3 -m mesostudies.manifest FOLDER --refresh "figures redrawn by studies/scripts/tablet_replot.py at COMMIT"
#   yade -n -x studies/scripts/tablet_replot.py FOLDER [FOLDER ...]
import json
import os
import sys

from mesocontact import batch
from mesostudies.tablet.campaign.common import read_csv
from mesostudies.tablet.campaign.plots import plot_cycles, plot_pull
from mesostudies.tablet import profile

batch.help_requested(sys.argv[1:], sys.argv[0], nargs=None)

for folder in sys.argv[1:]:
    variants = [f[:-len("fig16.json")] for f in os.listdir(folder) if f.endswith("-fig16.json")]
    for fig, mode in [("fig16", "tension"), ("fig18", "compression")] + [(v + "fig16", "tension") for v in variants]:
        js = os.path.join(folder, fig + ".json")
        if not os.path.exists(js):
            continue
        with open(js) as f:
            summary = json.load(f)
        runs = summary["runs"]
        data = {name: read_csv(os.path.join(folder, name + ".csv")) for name in runs}
        plot_cycles(mode, tuple(summary["amplitudes"]), tuple(summary["periods_crossings"]), runs, data,
                    os.path.join(folder, fig + ".png"), summary.get("quick", False),
                    variant=fig[:-len("fig16")].rstrip("-").replace("force-return", "back to the start's force")
                    .replace("kc", "kc/kp = "))
        print(f"{folder}/{fig}.png redrawn from {len(runs)} runs", flush=True)
    js = os.path.join(folder, "fig17.json")
    if os.path.exists(js):
        with open(js) as f:
            events = json.load(f)
        plot_pull(read_csv(os.path.join(folder, "fig17.csv")), events, os.path.join(folder, "fig17.png"))
        print(f"{folder}/fig17.png redrawn", flush=True)
    js = os.path.join(folder, "profile.json")
    if os.path.exists(js):
        with open(js) as f:
            info = json.load(f)
        profile.plot(info, read_csv(os.path.join(folder, "profile-slabs.csv")), os.path.join(folder, "profile.png"))
        print(f"{folder}/profile.png redrawn", flush=True)
