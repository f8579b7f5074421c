import copy
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CONFIGS = ROOT / "configs"
sys.path.insert(0, str(Path(__file__).parent))


def scene(name, **sections):
    """Load configs/NAME.toml with some keys overridden: scene("slider", film={"elements": 50})."""
    from sealts.scene.schema import scene_from_table
    table = tomllib.loads((CONFIGS / f"{name}.toml").read_text())
    table = copy.deepcopy(table)
    for sec, values in sections.items():
        if isinstance(values, dict):
            table.setdefault(sec, {}).update(values)
        else:
            table[sec] = values
    table.setdefault("output", {})["progress"] = False
    return scene_from_table(table, f"{name}.toml (test)", CONFIGS)


@pytest.fixture
def make_scene():
    return scene
