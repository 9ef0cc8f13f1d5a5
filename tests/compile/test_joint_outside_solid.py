"""A Joint with no Solid above it: Webots attaches no joint (WbBasicJoint::setJoint), its endPoint is free."""

from pathlib import Path

import mujoco
import pytest
from conftest import simulation_of

from wbtc.pipeline import compile_world

END_POINT = ("endPoint Solid { translation 0.3 0 0 children [ Shape { geometry DEF B Box { size 0.1 0.1 0.1 } } ] "
             "boundingObject USE B physics Physics { } }")
IN_POSE = f"""#VRML_SIM R2025a utf8
WorldInfo {{ }}
Pose {{
  translation 0 0 1
  children [
    HingeJoint {{
      jointParameters HingeJointParameters {{ axis 0 1 0 }}
      {END_POINT}
    }}
  ]
}}
"""
AT_TOP = f"""#VRML_SIM R2025a utf8
WorldInfo {{ }}
HingeJoint {{
  jointParameters HingeJointParameters {{ axis 0 1 0 anchor 0 0 1 }}
  {END_POINT.replace("translation 0.3 0 0", "translation 0.3 0 1")}
}}
"""


@pytest.mark.parametrize("text, line", [(IN_POSE, 6), (AT_TOP, 3)], ids=["in a top-level Pose", "at the top"])
def test_its_end_point_falls_freely_and_wbtc_says_why(tmp_path: Path, text: str, line: int) -> None:
    # MuJoCo refused both worlds before ("more than 6 dofs in body 'solid'": a free joint and the hinge).
    (tmp_path / "world.wbt").write_text(text, encoding="utf-8")
    result, _ = compile_world(tmp_path / "world.wbt")
    assert [mujoco.mjtJoint(t) for t in result.model.jnt_type] == [mujoco.mjtJoint.mjJNT_FREE]
    (warning,) = [w for w in result.warnings if "not inside a Solid" in w.message]
    assert warning.span.line == line
    sim = simulation_of(tmp_path, text)
    try:
        body = sim.model.nbody - 1
        assert sim.data.xpos[body] == pytest.approx([0.3, 0, 1])
        while sim.time < 0.3:
            sim.step()
        # It fell as a free body (0.44 m in 0.3 s), where a hinge about y would have swung it.
        assert sim.data.xpos[body][0] == pytest.approx(0.3, abs=1e-6)
        assert sim.data.xpos[body][2] == pytest.approx(1 - 9.81 * sim.time**2 / 2, abs=0.02)
    finally:
        sim.close()


def test_wbtc_check_lists_the_unattached_joint(tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from wbtc.cli import app

    (tmp_path / "world.wbt").write_text(IN_POSE, encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(tmp_path / "world.wbt")])
    assert result.exit_code == 0, result.output
    assert "warnings: 1" in result.stdout
    where = f"{tmp_path / 'world.wbt'}:6:5"
    assert f"{where}: warning: this HingeJoint is not inside a Solid" in result.stdout + result.stderr
