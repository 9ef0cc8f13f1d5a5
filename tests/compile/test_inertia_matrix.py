"""A written `inertiaMatrix` Webots finds invalid, or that MuJoCo refuses: warnings, and a model that loads.

Webots (WbPhysics) inserts a missing second line, drops lines past two, and leaves out a matrix whose
principal moments are not all positive or that is not positive definite, with its warnings. MuJoCo
refused all of these, and also a positive definite matrix whose principal moments no body could have
(A + B < C), which ODE takes: wbtc uses their mean (MuJoCo's balanceinertia), with a warning.
"""

from pathlib import Path

import pytest

from wbtc.runtime.launch import prepare

_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{ basicTimeStep 16 }}
Solid {{
  translation 0 0 0.5
  children [ DEF B Shape {{ geometry Box {{ size 0.1 0.2 0.3 }} }} ]
  boundingObject USE B
  physics Physics {{ density -1 mass 2 centerOfMass [ 0 0 0 ] inertiaMatrix [ {matrix} ] }}
}}
"""
# The box's own inertia for 2 kg: m (b^2 + c^2) / 12 and so on.
_BOX = [2 * (0.2**2 + 0.3**2) / 12, 2 * (0.1**2 + 0.3**2) / 12, 2 * (0.1**2 + 0.2**2) / 12]


@pytest.mark.parametrize(("matrix", "warnings", "inertia"), [
    ("0.1 0.2 0.25, 0 0 0", [], [0.1, 0.2, 0.25]),
    ("0.1 0.2 0.25", ["'inertiaMatrix' must have exactly 0 or 2 lines. Second line inserted."], [0.1, 0.2, 0.25]),
    ("0.1 0.2 0.25, 0 0 0, 1 1 1", ["'inertiaMatrix' must have exactly 0 or 2 lines. Extra lines skipped."],
     [0.1, 0.2, 0.25]),
    ("-1 1 1, 0 0 0", ["The first line of 'inertiaMatrix' (principal moments of inertia) must have only positive "
                       "values.", "'inertiaMatrix' must be positive definite."], _BOX),
    ("1 1 1, 2 0 0", ["'inertiaMatrix' must be positive definite."], _BOX),
    ("1 1 5, 0 0 0", ["'inertiaMatrix' has principal moments 1, 1, 5, which no body has (1 + 1 < 5): MuJoCo needs "
                      "a body's, so their mean 2.33333 is used"], [7 / 3] * 3),
])
def test_a_written_inertia_matrix_is_read_as_webots_reads_it(tmp_path: Path, matrix: str, warnings: list[str],
                                                             inertia: list[float]) -> None:
    world = tmp_path / "inertia.wbt"
    world.write_text(_WORLD.format(matrix=matrix))
    prepared = prepare(world)
    assert [w.message for w in prepared.warnings if "inertia" in w.message] == warnings
    model = prepared.sim.model
    assert sorted(model.body_inertia[1].tolist()) == pytest.approx(sorted(inertia), rel=1e-9)
    assert model.body_mass[1] == pytest.approx(2.0)
