"""ContactProperties' bounce tabled per pair of contact materials (wbtc.compile.bounce)."""

from pathlib import Path

import numpy as np
import pytest

from wbtc.compile.context import CompileOptions
from wbtc.pipeline import compile_world

_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {
  basicTimeStep 20
  contactProperties [
    ContactProperties { material1 "rubber" material2 "default" bounce 0.9 bounceVelocity 0.2 softCFM 0.01 }
    ContactProperties { material1 "default" material2 "rubber" bounce 0.1 }
    ContactProperties { material1 "rubber" material2 "rubber" bounce 0 }
  ]
}
Solid { boundingObject Plane { size 4 4 } }
Solid {
  translation 0 0 0.5
  contactMaterial "rubber"
  boundingObject Sphere { radius 0.1 }
  physics Physics { }
}
"""


def _table(tmp_path: Path, ode: bool = True):  # noqa: ANN202
    world = tmp_path / "bounce.wbt"
    world.write_text(_WORLD)
    result, _ = compile_world(world, CompileOptions(ode_contacts=ode))
    return result.model, result.table.bounce


def test_first_matching_contact_properties_in_either_order_and_defaults_otherwise(tmp_path):
    model, table = _table(tmp_path)
    assert table.materials == ["default", "rubber"]
    assert table.geom_class.tolist() == [0, 1]  # the plane (default), the ball (rubber)
    # (default, rubber): the first entry, written (rubber, default); the second is never reached.
    np.testing.assert_allclose(table.bounce, [[0.5, 0.9], [0.9, 0.0]])
    np.testing.assert_allclose(table.velocity, [[0.01, 0.2], [0.2, 0.01]])
    # ODE's R of a row in one 20 ms step: softCFM / basicTimeStep.
    np.testing.assert_allclose(table.regularisation, [[0.001 / 0.02, 0.01 / 0.02], [0.01 / 0.02, 0.001 / 0.02]])
    assert table.threshold == pytest.approx(0.01)


def test_only_with_ode_contacts(tmp_path):
    _, table = _table(tmp_path, ode=False)
    assert table is None
