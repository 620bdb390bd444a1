"""creaturelab's paper figures, each drawn from a run folder's HDF5 files alone.

One module per paper figure, named by the paper and its figure number (mehla_fig5_14.py is Mehla
2005 Fig. 5.14, rm_fig5.py is Rudolf & Mould 2009 Fig. 5), each with figures(RUN_DIR) -> [(name,
matplotlib Figure)], draw(run, out) -> [png paths] and a command line
(`/usr/bin/python3 analysis/figures/rm_fig5.py RUN_DIR`). Every figure follows analysis/style.py
(tests/analysis/check_figures.py checks them). runs.py reads run
folders; catalog.py says which figure belongs to which experiment and what the paper claims;
analysis/report.py writes report.html and REPORT.md from them.
"""
