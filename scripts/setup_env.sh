#!/usr/bin/env bash
# Set up the sealts environment on a Debian machine: system packages, a virtualenv with
# PETSc 3.26.1 + petsc4py built once from source, mpi4py on the same MPICH, and sealts itself.
#
# Idempotent and cheap on a second run: apt is skipped when the packages are present, and pip
# reuses its wheel cache (~/.cache/pip) for petsc and petsc4py. The first run compiles PETSc
# (about 7 minutes on 2 cores), petsc4py's Cython module (about 6) and mpi4py (about 1.5).
#
# Environment: SEALTS_VENV (default .venv) picks the virtualenv directory.
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
venv=${SEALTS_VENV:-$here/.venv}
PETSC_VERSION=3.26.1

# PETSc's configuration. Only the package registries are reachable, so nothing is downloaded by
# configure: MPI, BLAS/LAPACK, SuiteSparse (UMFPACK, KLU, CHOLMOD), SuperLU and METIS come from
# Debian. docs/petsc-build.md has the factorisation timings behind the choice.
PETSC_OPTS="--with-fc=0 --with-debugging=0 --with-mpi=1 --with-blaslapack-lib=-lopenblas \
--with-suitesparse=1 --with-suitesparse-include=/usr/include/suitesparse \
--with-suitesparse-lib=[-lspqr,-lumfpack,-lklu,-lcholmod,-lbtf,-lccolamd,-lcolamd,-lcamd,-lamd,-lsuitesparseconfig] \
--with-superlu=1 --with-superlu-include=/usr/include/superlu --with-superlu-lib=-lsuperlu \
--with-metis=1 COPTFLAGS=-O3 CXXOPTFLAGS=-O3"

say() { printf '[setup] %s\n' "$*"; }

# --- 1. system packages -------------------------------------------------------------------
apt_pkgs="mpich libmpich-dev libopenblas-dev libsuitesparse-dev libsuperlu-dev libmetis-dev \
patchelf pkg-config python3-venv libx11-6 libglu1-mesa libxcursor1 libxft2 libxinerama1"
missing=""
for p in $apt_pkgs; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    say "installing Debian packages:$missing"
    sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing >/dev/null
fi

# --- 2. virtualenv --------------------------------------------------------------------------
if [ ! -x "$venv/bin/python" ]; then
    say "creating virtualenv $venv"
    python3 -m venv "$venv"
fi
# shellcheck disable=SC1091
. "$venv/bin/activate"
py="$venv/bin/python"
pipq() { "$py" -m pip --disable-pip-version-check -q "$@"; }

pipq install "pip>=24" "setuptools>=77" wheel "cython>=3" "numpy>=1.26"

# --- 3. PETSc, built once -----------------------------------------------------------------
# pip's wheel cache keys the petsc wheel by version only, so the options it was built with are
# read back from the installed PETSc and compared; a mismatch rebuilds with --no-cache-dir.
petsc_opts_ok() {
    "$py" - "$PETSC_OPTS" <<'EOF' 2>/dev/null
import sys, os, petsc
want = set(sys.argv[1].split())
conf = os.path.join(petsc.get_petsc_dir(), "lib", "petsc", "conf", "petscvariables")
line = next(l for l in open(conf) if l.startswith("CONFIGURE_OPTIONS"))
have = {w.replace('\\', "").replace('"', "") for w in line.split("=", 1)[1].split()}
sys.exit(0 if want <= have else 1)
EOF
}
if ! "$py" -c "import petsc" 2>/dev/null || ! petsc_opts_ok; then
    export PETSC_CONFIGURE_OPTIONS="$PETSC_OPTS"
    say "installing petsc==$PETSC_VERSION (from the wheel cache, or a ~10 min build)"
    pipq install --no-build-isolation "petsc==$PETSC_VERSION"
    if ! petsc_opts_ok; then
        say "cached petsc wheel was built with other options: rebuilding without the cache"
        pipq install --no-build-isolation --no-cache-dir --force-reinstall --no-deps "petsc==$PETSC_VERSION"
    fi
fi
export PETSC_DIR
PETSC_DIR=$("$py" -c "import petsc; print(petsc.get_petsc_dir())")
unset PETSC_ARCH

if ! "$py" -c "import petsc4py" 2>/dev/null; then
    say "installing petsc4py==$PETSC_VERSION against $PETSC_DIR (from the wheel cache, or a ~8 min build)"
    pipq install --no-build-isolation "petsc4py==$PETSC_VERSION"
fi
# petsc4py records the absolute PETSc path of the venv it was first built in (RUNPATH and
# petsc.cfg). A wheel reused from pip's cache in another venv (a fresh clone) must load its
# own venv's PETSc, so both are pointed at the petsc package beside it.
so=$("$py" -c "import glob, os, petsc4py; print(glob.glob(os.path.join(os.path.dirname(petsc4py.__file__), 'lib', 'PETSc*.so'))[0])")
patchelf --set-rpath '$ORIGIN/../../petsc/lib' "$so"
printf 'PETSC_DIR  = %s\nPETSC_ARCH = \n' "$PETSC_DIR" > "$(dirname "$so")/petsc.cfg"
"$py" -c "from petsc4py import PETSc" || { echo "[setup] petsc4py does not import" >&2; exit 1; }

# --- 4. mpi4py on the same MPI, then sealts -------------------------------------------------
if ! "$py" -c "import mpi4py" 2>/dev/null; then
    say "installing mpi4py against $(command -v mpicc)"
    MPICC=mpicc pipq install --no-build-isolation --no-binary mpi4py "mpi4py>=4"
fi
pipq install --no-build-isolation -e "$here[test]"
say "ready: $venv"
