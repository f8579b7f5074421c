"""sealts: transient soft-EHL simulation of reciprocating rod seals on PETSc."""
import os

# OpenBLAS (under UMFPACK and numpy) spin-waits its threads. Measured on a 2-core machine,
# mounting a coarse O-ring: 1 thread 0.7 s system time, 2 threads 6.8 s, the same wall time;
# with a second busy process the spinning took the run from 1.5 to 14 min. MPI ranks are the
# parallelism here, so one BLAS thread per process unless the user says otherwise.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
