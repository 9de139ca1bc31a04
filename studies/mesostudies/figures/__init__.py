"""The papers' pair figures (inside ``yade``): ``common`` (what they share), ``long`` (long paper
Figs. 5-8), ``appendix`` (Figs. 9-15, adhesivity), ``short`` (short paper Figs. 5 and 6) and
``atlas`` (all of them behind one command, with the tablet's Figs. 16-19)."""
