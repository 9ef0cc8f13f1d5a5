"""wbtc's SolidRoundedBox: Webots' bounding object (3 boxes, 4 capsules along x, 8 cylinders), the mass a
density gives it (overlaps counted, as Webots), its parameter checks, and a box resting on the floor."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.runtime.simulation import Simulation
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 8\n}\n"


def _compile(tmp_path: Path, body: str):
    world = tmp_path / "rounded.wbt"
    world.write_text(HEADER + body)
    result, _ = compile_world(world)
    return result


def _collision_types(model: mujoco.MjModel, body: int) -> list[int]:
    return sorted(int(model.geom_type[g]) for g in range(model.ngeom)
                  if model.geom_bodyid[g] == body and model.geom_contype[g])


def test_default_box_collides_with_webots_primitives_and_weighs_their_volumes(tmp_path: Path) -> None:
    result = _compile(tmp_path, "DEF BOX SolidRoundedBox {\n  physics Physics {\n  }\n}\n")
    model = result.model
    body = model.body(result.table.bodies["BOX"]).id
    box, capsule, cylinder = (int(t) for t in (mujoco.mjtGeom.mjGEOM_BOX, mujoco.mjtGeom.mjGEOM_CAPSULE,
                                               mujoco.mjtGeom.mjGEOM_CYLINDER))
    assert _collision_types(model, body) == sorted([box] * 3 + [capsule] * 4 + [cylinder] * 8)
    # 2 m box, 0.5 m border: three 1 x 1 x 2 boxes, four capsules and eight cylinders of radius 0.5 and
    # length 1, their volumes added (overlaps included), at density 1000.
    capsules = 4 * (math.pi * 0.25 + 4 / 3 * math.pi * 0.125)
    cylinders = 8 * math.pi * 0.25
    assert model.body_mass[body] == pytest.approx(1000 * (6 + capsules + cylinders))
    drawn = [g for g in range(model.ngeom) if model.geom_bodyid[g] == body and not model.geom_contype[g]]
    assert len(drawn) == 15
    # The outermost points of the bounding object lie on the 2 m box.
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    top = max(data.geom_xpos[g][2] + (model.geom_size[g][0] if model.geom_type[g] != box else model.geom_size[g][2])
              for g in range(model.ngeom) if model.geom_bodyid[g] == body and model.geom_contype[g]
              and model.geom_type[g] != cylinder)
    assert top == pytest.approx(2.0)  # the default translation 0 0 1 puts it on the ground


def test_a_rounded_box_rests_on_its_bottom(tmp_path: Path) -> None:
    result = _compile(tmp_path, "Floor {\n}\nDEF BOX SolidRoundedBox {\n  translation 0 0 0.3\n"
                                "  size 0.4 0.3 0.2\n  borderRadius 0.05\n  physics Physics {\n  }\n}\n")
    body = result.model.body(result.table.bodies["BOX"]).id
    sim = Simulation(result, noise=False)
    for _ in range(150):  # 1.2 s
        sim.step()
    assert sim.data.xpos[body][2] == pytest.approx(0.1, abs=1.5e-3)
    assert abs(sim.data.xquat[body][0]) == pytest.approx(1, abs=1e-4)  # flat, not tipped over


def test_checks_and_edge_cases_as_webots(tmp_path: Path) -> None:
    def expand(fields: str):
        text = HEADER + f"SolidRoundedBox {{\n  {fields}\n}}\n"
        scene, expansion = expand_scene(build_scene(parse_text(text, str(tmp_path / "r.wbt"))), strict=True)
        return scene.nodes[1], expansion.console

    # A border radius of half every edge: a sphere.
    solid, console = expand("size 1 1 1\n  borderRadius 0.5")
    parts = solid.get("boundingObject").get("children")
    assert not console and len(parts) == 1
    sphere = parts[0].get("children")[0].get("geometry")
    assert sphere.type_name == "Sphere" and sphere.get("radius") == 0.5
    # Too large a radius is cut to half the smallest edge, with an error, as Webots.
    solid, console = expand("size 1 2 3\n  borderRadius 2\n  subdivision 4")
    assert len(console) == 2
    kinds = [p.get("children")[0].get("geometry") for p in solid.get("boundingObject").get("children")]
    # With the radius cut to 0.5 the inner x is 0: one box (full x) and no capsules, as in Webots; the
    # y and z edges are cylinders of the cut radius.
    assert sorted(g.type_name for g in kinds) == ["Box"] + ["Cylinder"] * 8
    assert {(g.get("radius"), g.get("subdivision")) for g in kinds[1:]} == {(0.5, 8)}
    solid, _ = expand("enableBoundingObject FALSE")
    assert solid.get("boundingObject") is None
