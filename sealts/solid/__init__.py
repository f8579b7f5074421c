"""The seal body: finite-strain kinematics, hyperelastic materials, Q1/P0 element kernels."""
