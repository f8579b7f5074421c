"""Units and scales: the one place that says what a number means.

sealts works in a consistent engineering unit system throughout -- scene files, unknowns,
output files:

=============  =========  =========================================
quantity       unit       notes
=============  =========  =========================================
length         mm         coordinates, film thickness, roughness
force          N
stress         MPa        = N/mm^2; fluid, asperity and solid stress
time           s
viscosity      MPa s      = N s/mm^2 (1e-8 MPa s = 10 mPa s)
velocity       mm/s
flow rate      mm^3/s     Q; per unit circumference q in mm^2/s
volume         mm^3       leakage V
=============  =========  =========================================

Scaling of the discrete system, so that PETSc tolerances mean something:

* Film pressure unknowns are in MPa; film rows are divided by a fixed positive row scale
  (their diagonal at the initial state, see :mod:`sealts.film.reynolds_fv`), so a film residual
  reads as a pressure error in MPa and ``-snes_atol 1e-10`` means 1e-10 MPa.
* The paper scheme's integration constants are c0 in mm^2/s (a flow per unit circumference)
  and y0 in mm; its rows are pressure differences in MPa.
* Leakage volumes are unknowns in mm^3; their rows (dV/dt - Q) are in mm^3/s.

Film thickness is printed in micrometres (um) in progress output and plots, because that is
what a seal engineer reads; files keep mm so that every column shares one unit system.
"""

# Pressures are gauge pressures (above the atmosphere's); the lowest a fluid can have is
# vacuum, one atmosphere below it
P_VACUUM = -0.101325      # MPa
