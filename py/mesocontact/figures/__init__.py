"""The papers' pair figures (inside ``yade``): ``common`` (what they share), ``long`` (long paper
Figs. 5-8), ``appendix`` (Figs. 9-15, adhesivity), ``short`` (short paper Figs. 5 and 6) and
``atlas`` (all of them behind one command, with the tablet's Figs. 16-19). The functions of
``long`` are also reachable here (``mesocontact.figures.fig5`` as before)."""
from .long import fig5, fig6_fig8, fig7  # noqa: F401
