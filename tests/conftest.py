import copy
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

from sealts.core import Recorder  # noqa: F401  (tests import it from here)

ROOT = Path(__file__).resolve().parents[1]
CONFIGS = ROOT / "configs"
sys.path.insert(0, str(Path(__file__).parent))


def load_script(name):
    """scripts/<name>.py as a module (registered in sys.modules, as its dataclasses need)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(name, ROOT / "scripts" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod
    spec.loader.exec_module(mod)
    return mod


def coarsened(sections):
    """The sections with the rule for coarsened meshes: a test that sets a scene's mesh
    sizes (h_contact or h_bulk) and not its h_edge gets ``h_edge = 0``. The shipped O-ring
    cycle refines its contact's edges to micrometres (mesh.h_edge), which would cost a
    coarsened test about the time the coarsening saves and move its numbers; a test about
    the refinement sets h_edge itself."""
    mesh = sections.get("mesh")
    if not isinstance(mesh, dict) or "h_edge" in mesh or not {"h_contact", "h_bulk"} & set(mesh):
        return sections
    return {**sections, "mesh": {**mesh, "h_edge": 0.0}}


def scene(name, **sections):
    """Load configs/NAME.toml with some keys overridden: scene("slider", film={"elements": 50});
    coarsened meshes as ``coarsened`` says."""
    from sealts.scene.schema import scene_from_table
    table = tomllib.loads((CONFIGS / f"{name}.toml").read_text())
    table = copy.deepcopy(table)
    sections = coarsened(sections)
    for sec, values in sections.items():
        if isinstance(values, dict):
            table.setdefault(sec, {}).update(values)
        else:
            table[sec] = values
    table.setdefault("output", {})["progress"] = False
    return scene_from_table(table, f"{name}.toml (test)", CONFIGS)


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return f'"{v}"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    return repr(v)


def config_text(name, **sections):
    """The text of configs/NAME.toml with keys set per section, for tests that run the CLI:
    config_text("oring_stroke", mesh={"h_contact": 0.1}). A key's line in its section is
    replaced (its comment dropped), a missing key is added under the section's header, a
    missing section at the end. Edits by key, so a changed value in the shipped file cannot
    silently escape a test's coarsening. Coarsened meshes as ``coarsened`` says."""
    lines = (CONFIGS / f"{name}.toml").read_text().splitlines()
    todo = {sec: dict(values) for sec, values in coarsened(sections).items()}
    out, sec = [], None
    for line in lines:
        head = line.strip()
        if head.startswith("[") and head.endswith("]") and not head.startswith("[["):
            sec = head[1:-1].strip()
            out.append(line)
            out += [f"{k} = {_toml_value(v)}" for k, v in todo.get(sec, {}).items()
                    if not any(ln.split("=")[0].strip() == k for ln in _section(lines, sec))]
            continue
        key = head.split("=")[0].strip() if "=" in head and not head.startswith("#") else None
        if sec in todo and key in todo[sec]:
            out.append(f"{key} = {_toml_value(todo[sec][key])}")
        else:
            out.append(line)
    present = {ln.strip()[1:-1].strip() for ln in lines if ln.strip().startswith("[")}
    for sec, values in todo.items():
        if sec not in present:
            out += ["", f"[{sec}]"] + [f"{k} = {_toml_value(v)}" for k, v in values.items()]
    return "\n".join(out) + "\n"


def _section(lines, name):
    """The lines of section [name]."""
    inside = False
    for line in lines:
        head = line.strip()
        if head.startswith("[") and head.endswith("]"):
            inside = head[1:-1].strip() == name
            continue
        if inside:
            yield line


def assert_jacobian_matches(pairs, J0, blocks, tol=1e-6):
    """Each (J, fd) of ``pairs`` (an assembled Jacobian and its central differences) agree
    over the dofs of ``blocks`` (name -> dofs) to ``tol`` of each row's largest entry (rows
    of tiny entries against 1e-8 of that row of J0), and within each block pair to ``tol``
    of the block's largest entry."""
    import numpy as np
    dofs = np.concatenate(list(blocks.values()))
    for J, fd in pairs:
        a, b = J[np.ix_(dofs, dofs)], fd[np.ix_(dofs, dofs)]
        scale = np.maximum(np.abs(a).max(1), 1e-8 * np.abs(J0[dofs]).max(1))
        err = np.abs(a - b).max(1) / scale
        assert err.max() <= tol, (dofs[err.argmax()], err.max())
        for rows in blocks.values():
            for cols in blocks.values():
                a, b = J[np.ix_(rows, cols)], fd[np.ix_(rows, cols)]
                assert np.abs(a - b).max() <= tol * max(np.abs(a).max(), np.abs(b).max())


def central_differences(problem, t, u, ud, blocks, eps, n):
    """dF/dU and dF/dU' of ``problem``'s residual (n x n) by central differences in the
    columns of ``blocks`` (name -> dofs), with the step ``eps[name]`` in U and 1e-2 in U'
    (the residuals are affine in U')."""
    import numpy as np
    fd_u, fd_ud = np.zeros((n, n)), np.zeros((n, n))
    for name, cols in blocks.items():
        for j in cols:
            e = np.zeros(n)
            e[j] = eps[name]
            fd_u[:, j] = (problem.residual(t, u + e, ud) - problem.residual(t, u - e, ud)) \
                / (2 * eps[name])
            e[j] = 1e-2
            fd_ud[:, j] = (problem.residual(t, u, ud + e) - problem.residual(t, u, ud - e)) \
                / 2e-2
    return fd_u, fd_ud


def mount_and_pressurise(s):
    """Steps 1-2 of a seal scene through the procedure (sealts.steps.prepare): the RunState
    with the model, u, t and the pressure front ``load``."""
    from sealts.steps import prepare
    return prepare(s)


def stroke_of(state, s=None):
    """The stroke's DAE (StrokeProblem) of scene s (default the state's) on a state of
    steps 1-2."""
    from sealts.problem.stroke_problem import StrokeProblem
    return StrokeProblem(state.model, state.u, s or state.scene, state.load)


def slips_off_the_kinks(rng, m, gamma_crit, width=1e-3):
    """m elastic slips (mm) from -1.5 to 1.5 gamma_crit, none within ``width`` gamma_crit of
    a kink of the friction law (phi's blend from 0.5, its saturation and the flow at 1), so
    that central differences over a smaller step see a smooth law."""
    x = rng.uniform(-1.5, 1.5, m)
    for k in (0.5, 1.0):
        near = np.abs(np.abs(x) - k) < width
        x[near] = np.sign(x[near]) * (k + 2 * width)
    return x * gamma_crit


def coarse_stroke(cache, **stroke):
    """The coarse O-ring (0.1/0.4 mm) of configs/oring_stroke.toml at 1 MPa, the rod ramped
    to 100 mm/s outstroke in 10 ms and held to 30 ms; ``stroke`` overrides those keys."""
    return scene("oring_stroke", mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(cache)},
                 stroke={"velocity": "ramp-hold", "v_max": 100.0, "t_ramp": 0.01,
                         "t_end": 0.03, "output_times": [], **stroke})


@pytest.fixture
def make_scene():
    return scene
