"""The lubricating film: Reynolds equation, flow factors, asperity contact, shear and leakage.

Modules
-------
gap           regularised film thickness used for conductance and storage
flow_factors  Patir-Cheng / tabulated pressure and shear flow factors (paper Eq. 13-14)
asperity      exponential asperity-contact law (Eq. 44)
reynolds_fv   default mass-conserving control-volume scheme for Eq. 13
paper_scheme  the paper's weighted pressure-gradient integration (Eq. 15-28)
quantities    shear stress, loads, friction and flow rate (Eq. 29-42)
seal_film     the film on the deforming seal's rod side, coupled to its displacements
"""
