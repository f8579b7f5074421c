"""scripts/bench_work_precision.py --reference --from-run takes only runs of the reference's
setting: the default scene's physics on the paper's mesh at stroke rtol 1e-4 (a run at
another sealed pressure or speed would make a wrong reference without a word)."""
import json
from dataclasses import asdict, replace

import pytest

from conftest import CONFIGS, load_script
from sealts.scene import load_scene


@pytest.fixture(scope="module")
def bench():
    return load_script("bench_work_precision")


def summary(**sections):
    """A finished run's summary of the default scene on the reference's mesh (grading 0.5),
    with ``sections`` replaced (name -> {key: value})."""
    s = load_scene(CONFIGS / "oring_stroke.toml")
    s = replace(s, mesh=replace(s.mesh, h_contact=0.01, h_bulk=0.05, h_edge=0.0,
                                grading_distance=0.5))
    for name, kw in sections.items():
        s = replace(s, **{name: replace(getattr(s, name), **kw)})
    scene = json.loads(json.dumps(asdict(s), default=str))
    return {"status": "finished", "provenance": {"scene": scene,
                                                 "solvers": {"stroke_": {"ts_rtol": 1e-4}}}}


def test_a_run_of_the_reference_setting_passes(bench):
    bench.check_reference_run(summary(stroke={"output_times": (2.5,)}), 0.5)


@pytest.mark.parametrize("sections, item", [
    ({"fluid": {"p_in": 10.0}}, "fluid.p_in = 10.0"),
    ({"stroke": {"v_max": 100.0}}, "stroke.v_max = 100.0"),
    ({"asperity": {"mu_s": 0.2}}, "asperity.mu_s = 0.2"),
    ({"mesh": {"h_edge": 0.0015}}, "mesh.h_edge = 0.0015"),
])
def test_a_run_of_another_setting_is_refused_naming_the_item(bench, sections, item):
    with pytest.raises(SystemExit) as e:
        bench.check_reference_run(summary(**sections), 0.5)
    assert item in str(e.value) and "the reference's is" in str(e.value)
