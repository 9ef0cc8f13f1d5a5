"""`wbtc compile`: the one-line summary, a loadable MJCF, errors and --strict without output files."""

from pathlib import Path

import mujoco
from typer.testing import CliRunner

from wbtc.cli import app

WORLDS = Path(__file__).parent / "fixtures" / "worlds"
runner = CliRunner()


def test_compile_prints_the_summary_and_writes_loadable_mjcf(tmp_path: Path) -> None:
    out = tmp_path / "robot.xml"
    result = runner.invoke(app, ["compile", str(WORLDS / "two_wheel_robot.wbt"), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines() == [
        f"{out}: 4 bodies, 3 joints, 2 actuators, 8 geoms, 1 robots, 7 devices",
    ]
    assert result.stderr == ""
    model = mujoco.MjModel.from_xml_path(str(out))
    assert (model.nbody - 1, model.njnt, model.nu, model.ngeom) == (4, 3, 2, 8)
    assert model.opt.timestep == 0.002
    assert sorted(p.name for p in tmp_path.iterdir()) == ["robot.xml"]  # no textures, no temporary files


def test_compile_writes_textures_beside_the_mjcf(tmp_path: Path) -> None:
    out = tmp_path / "lights.xml"
    result = runner.invoke(app, ["compile", str(WORLDS / "lights.wbt"), "--output", str(out)])
    assert result.exit_code == 0, result.output
    assert result.stdout.strip() == f"{out}: 1 bodies, 0 joints, 0 actuators, 5 geoms, 0 robots, 0 devices"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["lights.xml", "lights_assets"]
    assert len(list((tmp_path / "lights_assets").glob("*.png"))) == 1
    model = mujoco.MjModel.from_xml_path(str(out))
    assert model.ntex == 2  # the sky and the checker texture
    # Every shape has a material (its highlight, its share of the ambient light): a Material box, two PBR
    # spheres, the checker box and the shape without appearance.
    assert model.nmat == 5
    assert int((model.mat_texid[:, int(mujoco.mjtTextureRole.mjTEXROLE_RGB)] >= 0).sum()) == 1


def test_physics_step_option_sets_the_substep(tmp_path: Path) -> None:
    out = tmp_path / "t.xml"
    result = runner.invoke(app, ["compile", str(WORLDS / "timestep_32.wbt"), "-o", str(out), "--physics-step", "4"])
    assert result.exit_code == 0, result.output
    assert mujoco.MjModel.from_xml_path(str(out)).opt.timestep == 0.004


def test_world_with_an_error_exits_1_at_its_line_and_writes_nothing(tmp_path: Path) -> None:
    world = WORLDS / "syntax_error.wbt"
    out = tmp_path / "bad.xml"
    result = runner.invoke(app, ["compile", str(world), "-o", str(out)])
    assert result.exit_code == 1
    assert result.stderr.splitlines()[0] == f"{world}:7:3: error: unknown field 'boundingObjekt' in Solid"
    assert "Traceback" not in result.output
    assert result.stdout == ""
    assert list(tmp_path.iterdir()) == []


def test_missing_world_exits_1(tmp_path: Path) -> None:
    result = runner.invoke(app, ["compile", str(tmp_path / "none.wbt"), "-o", str(tmp_path / "none.xml")])
    assert result.exit_code == 1
    assert "no such world file" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_unhonoured_field_warns_and_still_compiles(tmp_path: Path) -> None:
    world = WORLDS / "locked_solid.wbt"
    out = tmp_path / "locked.xml"
    result = runner.invoke(app, ["compile", str(world), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert result.stderr.splitlines()[0] == (
        f"{world}:8:3: warning: Solid.locked is not honoured by wbtc yet; it is ignored")
    assert out.is_file()


def test_strict_turns_an_unhonoured_field_into_an_error(tmp_path: Path) -> None:
    world = WORLDS / "locked_solid.wbt"
    out = tmp_path / "locked.xml"
    result = runner.invoke(app, ["compile", str(world), "-o", str(out), "--strict"])
    assert result.exit_code == 1
    assert result.stderr.splitlines()[0] == (
        f"{world}:8:3: error: Solid.locked is not honoured by wbtc yet; it is ignored")
    assert result.stdout == ""
    assert list(tmp_path.iterdir()) == []


def test_compile_of_a_world_with_a_pen_writes_no_paint_layers(tmp_path: Path) -> None:
    # A Pen makes every shape paintable in a run (a texture and material of its own each); plain MuJoCo
    # has no pen, so the MJCF keeps the shapes' shared textures: here one checker texture for two boxes.
    world = tmp_path / "pen.wbt"
    world.write_text("""#VRML_SIM R2025a utf8
WorldInfo { }
DEF A Solid { children [ Shape { appearance PBRAppearance { baseColorMap ImageTexture { url "checker.png" } }
  geometry Box { size 1 1 0.1 } } ] }
DEF B Solid { translation 2 0 0 children [ Shape { appearance PBRAppearance { baseColorMap ImageTexture {
  url "checker.png" } } geometry Box { size 1 1 0.1 } } ] }
Robot { children [ Pen { } ] }
""", encoding="utf-8")
    from PIL import Image

    Image.new("RGB", (8, 8), (200, 30, 30)).save(tmp_path / "checker.png")
    out = tmp_path / "pen.xml"
    result = runner.invoke(app, ["compile", str(world), "-o", str(out)])
    assert result.exit_code == 0, result.output
    model = mujoco.MjModel.from_xml_path(str(out))
    names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_TEXTURE, t) or "" for t in range(model.ntex)]
    assert not [name for name in names if name.startswith("paint_")]
    assert model.ntex == 1
    # A run of the same world paints: each box has its own layer.
    from wbtc.pipeline import compile_world

    run_model = compile_world(world)[0].model
    painted = [mujoco.mj_id2name(run_model, mujoco.mjtObj.mjOBJ_TEXTURE, t) or "" for t in range(run_model.ntex)]
    assert len([name for name in painted if name.startswith("paint_")]) == 2


def test_compile_into_a_missing_folder_says_so_before_compiling(tmp_path: Path, monkeypatch) -> None:
    import wbtc.pipeline

    def never(*args, **kwargs):
        raise AssertionError("compiled although the output folder is missing")

    monkeypatch.setattr(wbtc.pipeline, "compile_world", never)
    out = tmp_path / "missing" / "robot.xml"
    result = runner.invoke(app, ["compile", str(WORLDS / "two_wheel_robot.wbt"), "-o", str(out)])
    assert result.exit_code == 1
    assert result.stderr.strip() == f"error: the output folder {out.parent} does not exist"
    assert not (tmp_path / "missing").exists()
