"""Deeply nested worlds load and run: Webots has no nesting limit, Python's default recursion limit had one.

A chain robot of 150 links (each a HingeJoint and its Solid, in the last link's children) stopped
`wbtc check` and `wbtc run` with a RecursionError traceback.
"""

from pathlib import Path

import pytest
from typer.testing import CliRunner

from wbtc.cli import app

_LINK = ("HingeJoint { jointParameters HingeJointParameters { axis 1 0 0 } endPoint Solid { translation 0 0 -0.01 "
         "children [ DEF L Shape { geometry Box { size 0.005 0.005 0.01 } } ")
_END = " ] boundingObject USE L physics Physics { density -1 mass 0.01 } } }"


def test_a_chain_of_300_links_hangs_from_its_robot(tmp_path: Path) -> None:
    world = tmp_path / "chain.wbt"
    world.write_text("#VRML_SIM R2023b utf8\nWorldInfo { basicTimeStep 16 }\n"
                     f"Robot {{ translation 0 0 4 children [ {_LINK * 300}{_END * 300} ] }}\n")
    result = CliRunner().invoke(app, ["check", "--json", str(world)])
    assert result.exit_code == 0, result.output
    from wbtc.runtime.launch import prepare

    sim = prepare(world).sim
    assert sim.model.njnt == 300
    for _ in range(10):
        sim.step()
    # The links hang straight down from the robot, 1 cm each: the last one's centre 3 m below it.
    last = sim.model.nbody - 1
    assert sim.data.xpos[last][2] == pytest.approx(4 - 3.0, abs=1e-3)


def test_solids_nested_1000_deep_load(tmp_path: Path) -> None:
    world = tmp_path / "deep.wbt"
    world.write_text("#VRML_SIM R2023b utf8\nWorldInfo { basicTimeStep 16 }\n"
                     + "Solid { children [ " * 1000 + "Solid { }" + " ] }" * 1000 + "\n")
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.1"])
    assert result.exit_code == 0, result.output
    assert "Traceback" not in result.output
