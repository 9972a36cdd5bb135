"""Analyses of Orogen's results that the charts, the statistics and the evidence share.

    powerlaw             growth laws H = a (S - S0)^b and the Simple Model (thesis 4.3, 5.4.6)
    cycles               thrust-sheet step-outs of a front (5.4.5-5.4.7)
    surface              the model's surface, profile fits and Dahlen's critical taper
    calibrated_taper     the critical taper of a run's calibrated material (orogen calibrate)
    exhumation           analysis.h5 as xarray, the pro cycle (chapter 6)
    exhumation_summary   chapter 6's indicators per run  (python3 -m orogen.analysis.exhumation_summary)
    traction             what the bases transmit          (python3 -m orogen.analysis.traction)
    stress               the wedge's interior stress      (python3 -m orogen.analysis.stress)
    basins               what the foreland basins record: deposits kept, parcels' subsidence
                                                          (python3 -m orogen.analysis.basins)
"""
