"""Specular highlights as Webots draws them: none for a default Material, a metal's in its own colour."""

from pathlib import Path

import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
}
Background {
  skyColor [0 0 0]
}
DirectionalLight {
  direction 0 0 -1
  intensity 1
}
Viewpoint {
  position 0 0 3
  orientation 0 1 0 1.5708
}
DEF LOOK Shape {
  appearance %s
  geometry Sphere {
    radius 0.5
    subdivision 4
  }
}
"""


def _material(tmp_path: Path, appearance: str) -> tuple[float, float, object]:
    world = tmp_path / "look.wbt"
    world.write_text(WORLD % appearance)
    result, _ = compile_world(world)
    model = result.model
    geom = next(g for g in range(model.ngeom) if model.geom_matid[g] >= 0)
    mat = int(model.geom_matid[geom])
    return float(model.mat_specular[mat]), float(model.mat_shininess[mat]), result


@pytest.mark.parametrize(("appearance", "specular", "shininess"), [
    ("Appearance { material Material { diffuseColor 1 0 0 } }", 0.0, 0.2),
    ("Appearance { material Material { diffuseColor 1 0 0 specularColor 0.6 0.3 0.3 shininess 0.8 } }", 0.4, 0.8),
    ("PBRAppearance { baseColor 0 0 0 roughness 0 metalness 1 }", 0.0, 1.0),
    ("PBRAppearance { baseColor 0.5 0.5 0.5 roughness 0.2 metalness 0 }", 0.4, 0.8),
    ("PBRAppearance { baseColor 0.5 0.5 0.5 roughness 0.2 metalness 1 }", 0.2, 0.8),
    # A blue metal reflects no red: MuJoCo's white highlight takes the weakest channel (none here).
    ("PBRAppearance { baseColor 0 0 1 roughness 0 metalness 1 }", 0.0, 1.0),
    # Half metal: half a dielectric's white highlight, half the weakest channel's.
    ("PBRAppearance { baseColor 1 0.8 0.2 roughness 0 metalness 0.5 }", 0.5 * (0.5 + 0.5 * 0.2), 1.0),
])
def test_material_specular_and_shininess(tmp_path: Path, appearance: str, specular: float, shininess: float):
    got_specular, got_shininess, _ = _material(tmp_path, appearance)
    assert got_specular == pytest.approx(specular)
    assert got_shininess == pytest.approx(shininess)


def test_a_black_metal_sphere_under_a_light_shows_no_white_highlight(tmp_path: Path):
    _, _, result = _material(tmp_path, "PBRAppearance { baseColor 0 0 0 roughness 0 metalness 1 }")
    sim = Simulation(result, noise=False)
    image = sim.render(-1, 64, 64)
    assert int(np.max(image)) < 30  # black everywhere: no highlight on the sphere
