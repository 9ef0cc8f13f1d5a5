"""Primitive sizes that are not positive: Webots changes them to 1 with a warning (its nodes' sanitizeFields).

A Box of size 0 0 0 is a 1 m box in Webots; a Cone of height 0 made MuJoCo refuse the whole model (a
mesh without volume), and a Plane of size 0 0 as a bounding object too.
"""

from pathlib import Path

import mujoco
import pytest
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.runtime.launch import prepare

_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{ basicTimeStep 16 }}
Solid {{ translation 0 0 0.5 children [ DEF G Shape {{ geometry {geometry} }} ] boundingObject USE G }}
"""


@pytest.mark.parametrize(("geometry", "warnings", "geom_type", "size"), [
    ("Box { size 0 0.2 0.2 }", ["Invalid 'size' changed to 1 1 1."], mujoco.mjtGeom.mjGEOM_BOX, [0.5, 0.5, 0.5]),
    ("Sphere { radius -0.1 }", ["Invalid 'radius' changed to 1."], mujoco.mjtGeom.mjGEOM_SPHERE, [1.0]),
    ("Cylinder { radius 0.1 height 0 }", ["Invalid 'height' changed to 1."], mujoco.mjtGeom.mjGEOM_CYLINDER,
     [0.1, 0.5]),
    ("Capsule { radius 0 height 0.3 }", ["Invalid 'radius' changed to 1."], mujoco.mjtGeom.mjGEOM_CAPSULE,
     [1.0, 0.15]),
    ("Cone { bottomRadius 0 height 0 }", ["Invalid 'bottomRadius' changed to 1.", "Invalid 'height' changed to 1."],
     mujoco.mjtGeom.mjGEOM_MESH, None),
    ("Plane { size 0 0 }", ["Invalid 'size' changed to 1 1."], mujoco.mjtGeom.mjGEOM_PLANE, [0.5, 0.5]),
])
def test_a_size_not_positive_is_changed_to_one(tmp_path: Path, geometry: str, warnings: list[str], geom_type,
                                               size: list[float] | None) -> None:
    world = tmp_path / "sizes.wbt"
    world.write_text(_WORLD.format(geometry=geometry))
    prepared = prepare(world)
    said = [w.message for w in prepared.warnings if "changed to" in w.message]
    assert said == [f"{w} The value should be positive." for w in warnings]
    model = prepared.sim.model
    geoms = [g for g in range(model.ngeom) if model.geom_type[g] == geom_type]
    assert geoms
    if size is not None:
        assert model.geom_size[geoms[0]][:len(size)].tolist() == pytest.approx(size)
    # `wbtc check` says so too, with the field's place.
    output = CliRunner().invoke(app, ["check", str(world)]).output
    for w in warnings:
        assert f"warning: {w} The value should be positive." in output
