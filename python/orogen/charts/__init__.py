"""Charts of Orogen's results (matplotlib, Agg: no display needed), one module per kind of run,
each a command: `python3 -m orogen.charts.wedge RUN [RUN...] --out DIR`, or `orogen charts RUN`.

    wedge              doubly-vergent wedge runs: height, tapers, fronts, topography, basal slip
    granular           repose, singly-vergent and biaxial runs and sweeps (chapter 3)
    ensemble           an ensemble's aggregate: Figs 5.14-5.22
    exhumation         a run's analysis.h5 (orogen analyze): chapter 6's figures
    exhumation_frames  frames and animations of the analysed horizons
"""
