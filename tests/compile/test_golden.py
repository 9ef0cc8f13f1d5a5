"""Golden MJCF: small worlds compiled and written with `MjSpec.to_xml()` must match tests/compile/golden/.

The worlds (tests/compile/fixtures/worlds) cover a two-wheel robot made of base nodes (Robot, Solid,
HingeJoint, RotationalMotor, PositionSensor, DistanceSensor, Camera, LED), every primitive geometry with a
scaled Transform, a slider + Hinge2Joint + BallJoint mechanism, an ElevationGrid and an IndexedFaceSet,
lights and Material/PBRAppearance colours with a texture, and an NUE world written before R2022a.

The worlds are compiled from their own folder with a relative path, so texture names (a hash of the
texture's path) do not depend on where the repository is checked out.

To accept new output after an intended compiler change, run
`WBTC_REGEN_GOLDEN=1 python -m pytest tests/compile/test_golden.py`, then read the diff of
tests/compile/golden/ against the worlds before committing it.
"""

import os
from pathlib import Path

import mujoco
import pytest

from wbtc.compile.output import write_mjcf
from wbtc.pipeline import compile_world

WORLDS = Path(__file__).parent / "fixtures" / "worlds"
GOLDEN = Path(__file__).parent / "golden"
REGENERATE = os.environ.get("WBTC_REGEN_GOLDEN") == "1"

#: World name -> (bodies without the world body, joints, actuators, geoms, robots, devices).
CASES = {
    "two_wheel_robot": (4, 3, 2, 8, 1, 7),
    "primitives": (7, 0, 0, 15, 0, 0),
    "mechanism": (4, 4, 3, 3, 1, 4),
    "meshes": (2, 1, 0, 4, 0, 0),
    "lights": (1, 0, 0, 5, 0, 0),
    "nue_legacy": (3, 2, 1, 5, 1, 2),
}


def _compile(name: str, monkeypatch: pytest.MonkeyPatch):
    monkeypatch.chdir(WORLDS)
    result, expansion = compile_world(f"{name}.wbt")
    assert expansion.warnings == [] and result.warnings == [], (expansion.warnings, result.warnings)
    return result


def _counts(model: mujoco.MjModel) -> tuple[int, int, int, int]:
    return model.nbody - 1, model.njnt, model.nu, model.ngeom


@pytest.mark.parametrize("name", sorted(CASES))
def test_mjcf_matches_golden(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    result = _compile(name, monkeypatch)
    bodies, joints, actuators, geoms, robots, devices = CASES[name]
    assert _counts(result.model) == (bodies, joints, actuators, geoms)
    assert len(result.table.robots) == robots
    assert sum(len(r.devices) for r in result.table.robots) == devices
    xml = result.spec.to_xml()
    golden = GOLDEN / f"{name}.xml"
    if REGENERATE:
        golden.write_text(xml, encoding="utf-8")
    assert golden.is_file(), f"no golden file {golden}: run with WBTC_REGEN_GOLDEN=1 and review it"
    assert xml == golden.read_text(encoding="utf-8")


@pytest.mark.parametrize("name", sorted(CASES))
def test_written_mjcf_loads_in_mujoco(name: str, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    result = _compile(name, monkeypatch)
    out = tmp_path / f"{name}.xml"
    written = write_mjcf(result.spec, out)
    assert written[0] == out and all(path.is_file() for path in written)
    assert len(written) == 1 + len(result.spec.assets)
    model = mujoco.MjModel.from_xml_path(str(out))
    assert _counts(model) == _counts(result.model)
    assert (model.ntex, model.nmat, model.nmesh, model.nhfield, model.nlight, model.ncam) == (
        result.model.ntex, result.model.nmat, result.model.nmesh, result.model.nhfield, result.model.nlight,
        result.model.ncam)
    assert model.opt.timestep == result.model.opt.timestep
    assert model.actuator_gainprm[:, 0].tolist() == pytest.approx(result.model.actuator_gainprm[:, 0].tolist(),
                                                                  rel=1e-5)
    # The written model steps like the compiled one (the XML keeps 6 significant digits).
    data = mujoco.MjData(model)
    for _ in range(100):
        mujoco.mj_step(model, data)
    assert all(data.warning[i].number == 0 for i in range(len(data.warning)))
