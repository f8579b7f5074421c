"""What a run needs to be repeated: the resolved scene (every key with its value, defaults
included), the PETSc options given (command line and the scene's [petsc] table), the
solvers in force by options prefix (types and tolerances after setFromOptions, the
defaults sealts sets included), and the versions of sealts, its git commit, PETSc,
petsc4py, numpy, numba and Python. Recorded in ``summary.json`` as ``provenance``."""
import dataclasses
import platform
import subprocess
from importlib import metadata
from pathlib import Path


def _version(name):
    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        return None


def git_commit():
    """The commit of the sealts checkout this package runs from ("+" when its files differ
    from it), or None outside a git checkout."""
    root = Path(__file__).resolve().parents[2]
    if not (root / ".git").exists():
        return None
    try:
        run = dict(cwd=root, capture_output=True, text=True, timeout=10, check=True)
        head = subprocess.run(["git", "rev-parse", "HEAD"], **run).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--", "sealts"],
                               **run).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return None
    return head + ("+" if dirty else "")


def provenance(scene, petsc_options):
    from petsc4py import PETSc

    from ..problem.problem import SOLVERS
    return {
        "scene": dataclasses.asdict(scene),
        "petsc_options": dict(petsc_options),
        "solvers": {prefix or "(none)": dict(s) for prefix, s in SOLVERS.items()},
        "sealts_version": _version("sealts"),
        "git_commit": git_commit(),
        "petsc_version": "%d.%d.%d" % PETSc.Sys.getVersion(),
        "petsc4py_version": _version("petsc4py"),
        "numpy_version": _version("numpy"),
        "numba_version": _version("numba"),
        "python_version": platform.python_version(),
    }
