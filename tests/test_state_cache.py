"""The pressurised-state cache (sealts/steps/state_cache.py): a second run of a stroke
mounts nothing and gives the same stroke; a changed input never reuses a stale state."""
import json
import subprocess
import sys
from dataclasses import replace
from pathlib import Path


from conftest import config_text, scene

ROOT = Path(__file__).resolve().parents[1]


def test_key_changes_with_every_input_of_steps_1_2_and_only_with_them(tmp_path,
                                                                      monkeypatch):
    from sealts.steps import state_cache
    from sealts.steps.state_cache import key
    base = scene("oring_stroke", mesh={"cache": str(tmp_path)})
    k0 = key(base, {"stroke_ts_rtol": "1e-3"})

    def sec(name, **kw):
        return replace(base, **{name: replace(getattr(base, name), **kw)})

    # the stroke's own inputs, names and reports: the same state
    same = [sec("stroke", v_max=100.0), sec("fluid", viscosity=2e-8),
            sec("asperity", mu_s=0.3), sec("groove", mu=0.2), sec("output", plot=False),
            sec("film", squeeze=False), replace(base, name="other", description="x"),
            sec("mesh", cache=str(tmp_path / "elsewhere"))]
    for s in same:
        assert key(s, {"stroke_ts_rtol": "1e-3"}) == k0
    assert key(base, {"stroke_ts_rtol": "1e-5", "ts_monitor": "", "log_view": "",
                      "snes_converged_reason": ""}) == k0
    # what steps 1-2 read: another state each
    other = [sec("fluid", p_in=2.0), sec("fluid", p_out=0.5), sec("fluid", p_crit=0.2),
             sec("mesh", h_contact=0.05), sec("mesh", h_edge=0.002),
             sec("mesh", h_edge=0.0), sec("mesh", edge_span=0.1),
             sec("mesh", symmetric=True, h_edge=0.0),
             sec("material", c10=1.1), sec("material", temperature_rise=10.0),
             sec("asperity", h_mix=8e-4), sec("asperity", p_mix=10.0),
             sec("groove", diameter=59.5), sec("groove", clearance=0.1),
             sec("rod", radius=25.01), sec("seal", d2=5.34), sec("mount", penalty=2e4),
             sec("mount", dt=0.01), sec("seal", self_contact="on")]
    keys = [key(s, {"stroke_ts_rtol": "1e-3"}) for s in other]
    keys += [key(base, {"ts_rtol": "1e-2"}), key(base, {"static_snes_rtol": "1e-12"}),
             key(base, {"transfer_snes_max_it": "60"}),
             key(base, {"pc_factor_mat_solver_type": "petsc"})]
    monkeypatch.setattr(state_cache, "code_version", lambda: "a changed line of sealts")
    keys.append(key(base, {"stroke_ts_rtol": "1e-3"}))
    assert k0 not in keys and len(set(keys)) == len(keys)


def test_a_hold_to_a_high_pressure_has_the_self_contact_and_its_own_state():
    """seal.self_contact = "auto" reads hold.p_end as it reads p_in: the O-ring's surface
    creases against the wall from 38 MPa whichever step raises the pressure (stress.md,
    twenty-second session), and steps 1-2 take the self-contact's term, so a hold to 20 MPa
    and one to 5 MPa from the same p_in have different states."""
    from sealts.problem.seal_model import SELF_CONTACT_FROM, self_contact_on
    from sealts.steps.state_cache import key
    base = scene("oring_hold")
    assert base.fluid.p_in < SELF_CONTACT_FROM and base.seal.self_contact == "auto"

    def hold(p):
        return replace(base, hold=replace(base.hold, p_end=p))

    assert not self_contact_on(hold(5.0)) and self_contact_on(hold(SELF_CONTACT_FROM))
    assert key(hold(20.0)) != key(hold(5.0))
    assert key(hold(5.0)) == key(hold(9.0))          # no other hold input reaches steps 1-2


def test_steps_with_and_without_the_cache(tmp_path):
    from sealts.steps import steps_for

    def names(s, command="run"):
        return [type(step).__name__ for step in steps_for(s, command)]

    cache = {"cache": str(tmp_path)}
    assert names(scene("oring_stroke", mesh=cache)) == \
        ["Mount", "Pressurise", "SaveToCache", "Checkpoint", "Stroke"]
    assert names(scene("oring_stroke", mesh=cache, start={"cache": False})) == \
        ["Mount", "Pressurise", "Checkpoint", "Stroke"]
    # nothing after steps 1-2: nothing to cache for
    assert names(scene("oring_mount", mesh=cache)) == ["Mount", "Checkpoint"]


def _run(tmp_path, tag, **sections):
    text = config_text("oring_stroke", mesh={"h_contact": 0.1, "h_bulk": 0.4,
                                             "cache": str(tmp_path / "cache")},
                       stroke={"t_end": 0.1, "output_times": [0.05]},
                       output={"plot": False, "progress": True}, **sections)
    path = tmp_path / f"{tag}.toml"
    path.write_text(text)
    out = tmp_path / tag
    r = subprocess.run([sys.executable, "-m", "sealts", "run", str(path), "-o", str(out)],
                       capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr[-2000:]
    return json.loads((out / "summary.json").read_text()), r.stdout


def test_a_second_run_mounts_nothing_and_strokes_the_same(tmp_path):
    first, _ = _run(tmp_path, "first")
    assert first["steps_1_2"]["from"] == "computed"
    entry = Path(first["steps_1_2"]["cache"])
    assert entry.is_file()
    second, said = _run(tmp_path, "second", fluid={"viscosity": 1e-8})
    assert second["steps_1_2"] == {"from": "cache", "cache": str(entry)}
    assert "from the state cache" in said
    # the same pressurised seal, hence the same stroke to the last bit
    assert second["results"]["mounted"] == first["results"]["mounted"]
    assert second["stroke"]["leakage_out"] == first["stroke"]["leakage_out"]
    assert second["stroke"]["friction_work"] == first["stroke"]["friction_work"]
    assert second["steps_accepted"] == first["stroke"]["steps_accepted"]
    # another sealed pressure: computed, its own entry
    third, _ = _run(tmp_path, "third", fluid={"p_in": 2.0})
    assert third["steps_1_2"]["from"] == "computed"
    assert Path(third["steps_1_2"]["cache"]) != entry
    assert third["results"]["contact_force_total"] > first["results"]["contact_force_total"]
    # an entry that cannot be read is recomputed and replaced
    entry.write_bytes(b"not a state")
    fourth, said = _run(tmp_path, "fourth")
    assert fourth["steps_1_2"]["from"] == "computed" and "cannot be read" in said
    assert fourth["stroke"]["leakage_out"] == first["stroke"]["leakage_out"]
    fifth, _ = _run(tmp_path, "fifth")
    assert fifth["steps_1_2"]["from"] == "cache"


def test_rank_0_writes_the_entry_whatever_the_state_s_writer(tmp_path):
    """The cache entry is rank 0's to write, also where the state's writer writes nothing:
    mesh.h_edge runs steps 1-2 on the scene's own mesh with such a writer, and their entry
    was never written, so every h_edge study remounted. A state saved that way reads back
    as the state it was."""
    import numpy as np

    from sealts.steps import new_state
    from sealts.steps.state import read_state
    from sealts.steps.state_cache import SaveToCache, StateCache
    s = scene("oring_stroke", mesh={"h_contact": 0.1, "h_bulk": 0.4, "cache": str(tmp_path)},
              output={"progress": False})
    st = new_state(s)
    assert not st.writer.root                 # a NullWriter
    st.u = np.linspace(0.0, 1e-3, st.model.n)
    entry = StateCache(s)
    SaveToCache(entry).run(st)
    un, X, _, attrs = read_state(entry.path)
    assert np.array_equal(X, st.model.mesh.X) and np.array_equal(un, st.u[st.model.udofs])
    assert attrs["p_in"] == s.fluid.p_in
