"""Scene files: TOML in mm, N, s, MPa, parsed into frozen dataclasses and validated."""
from .errors import SceneError
from .schema import Scene, default_scene, load_scene, parse_scene

__all__ = ["Scene", "SceneError", "default_scene", "load_scene", "parse_scene"]
