"""The world cache: a world run again starts from what its last load and compile gave, until anything
it was made from changes."""

import os
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from wbtc import pipeline, world_cache
from wbtc.compile.context import CompileOptions
from wbtc.proto import resolve
from wbtc.scene.model import walk

WORLD = """#VRML_SIM R2022a utf8
WorldInfo { basicTimeStep 16 }
Thing { size 0.1 0.1 0.1 }
Solid {
  translation 1 0 0.5
  children [
    Shape { appearance Appearance { texture ImageTexture { url [ "skin.png" ] } } geometry Box { size 0.2 0.2 0.2 } }
  ]
}
Robot { name "r" children [ DistanceSensor { name "ds" } ] controller "<none>" }
"""

THING = """#VRML_SIM R2022a utf8
PROTO Thing [ field SFVec3f size 0.1 0.1 0.1 ]
{
  Solid { children [ Shape { geometry Box { size IS size } } ] boundingObject Box { size 0.3 0.3 0.3 } }
}
"""

RANDOM = """#VRML_SIM R2022a utf8
# tags: nonDeterministic
# template language: javascript
PROTO Random [ ]
{
  %< import * as wbrandom from 'wbrandom.js'; >%
  Solid { translation %<= wbrandom.real() >% 0 0 }
}
"""


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    folder = tmp_path / "cache"  # beside the world's folder, as ~/.cache is beside a user's projects
    monkeypatch.setenv("WBTC_CACHE_DIR", str(folder))
    monkeypatch.delenv("WBTC_NO_CACHE", raising=False)
    return folder


@pytest.fixture
def world(tmp_path: Path) -> Path:
    (tmp_path / "project" / "protos").mkdir(parents=True)
    (tmp_path / "project" / "protos" / "Thing.proto").write_text(THING, encoding="utf-8")
    path = tmp_path / "project" / "world.wbt"
    path.write_text(WORLD, encoding="utf-8")
    return path


def _loads(monkeypatch: pytest.MonkeyPatch) -> list[Path]:
    """Count the real loads from now on (a result taken from the cache loads nothing)."""
    calls: list[Path] = []
    real = pipeline.load_world

    def counting(path, strict=False):
        calls.append(Path(path))
        resolve._project_index.cache_clear()  # a process lists a project's PROTO folders once; tests edit them
        return real(path, strict)

    monkeypatch.setattr(pipeline, "load_world", counting)
    return calls


def _touch_later(path: Path, text: str) -> None:
    """Rewrite a file and make sure its modification time moves on (coarse file system clocks)."""
    before = path.stat().st_mtime_ns
    path.write_text(text, encoding="utf-8")
    if path.stat().st_mtime_ns == before:
        os.utime(path, ns=(before + 1_000_000, before + 1_000_000))


def test_a_world_run_again_comes_from_the_cache_with_its_nodes_shared(cache, world, monkeypatch):
    loads = _loads(monkeypatch)
    scene, expansion, first = world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 1 and len(list(cache.glob("*.pickle"))) == 1
    scene2, expansion2, second = world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 1  # nothing parsed or compiled the second time
    assert (second.model.nbody, second.model.ngeom) == (first.model.nbody, first.model.ngeom)
    np.testing.assert_array_equal(second.model.geom_size, first.model.geom_size)
    assert expansion2.counts == expansion.counts == {"Thing": 1}
    assert [w.message for w in second.warnings] == [w.message for w in first.warnings]
    # The table's device nodes are the cached scene's own nodes (supervisor calls compare them by identity).
    sensor = second.table.robots[0].devices[0]
    assert sensor.name == "ds" and any(node is sensor.node for node in walk(scene2.nodes))
    # The table's Solids (keyed by id(node)) are the cached scene's nodes too (supervisor getPosition & co).
    solids = {id(node): node for node in walk(scene2.nodes) if node.is_a("Solid")}
    assert len(second.table.solids) == len(first.table.solids) > 0
    assert set(second.table.solids) <= set(solids)


def test_options_and_no_cache_give_their_own_results(cache, world, monkeypatch):
    loads = _loads(monkeypatch)
    world_cache.load_and_compile(world, CompileOptions())
    world_cache.load_and_compile(world, CompileOptions(max_substep_ms=1.0))  # another entry
    assert len(loads) == 2 and len(list(cache.glob("*.pickle"))) == 2
    monkeypatch.setenv("WBTC_NO_CACHE", "1")
    world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 3


def test_editing_the_world_or_a_proto_compiles_again(cache, world, monkeypatch):
    loads = _loads(monkeypatch)
    world_cache.load_and_compile(world, CompileOptions())
    _touch_later(world, WORLD.replace("Thing { size 0.1 0.1 0.1 }", "Thing { size 0.4 0.4 0.4 }"))
    _, _, result = world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 2
    assert np.isclose(result.model.geom_size[:, 0], 0.2).any()  # the 0.4 box's half size
    proto = world.parent / "protos" / "Thing.proto"
    _touch_later(proto, THING.replace("0.3 0.3 0.3", "0.5 0.5 0.5"))
    _, _, result = world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 3
    assert np.isclose(result.model.geom_size[:, 0], 0.25).any()
    world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 3  # unchanged since: from the cache again


def test_a_texture_that_appears_later_is_seen(cache, world, monkeypatch):
    loads = _loads(monkeypatch)
    _, _, first = world_cache.load_and_compile(world, CompileOptions())
    assert first.model.ntex == 0 and any("skin.png" in w.message for w in first.warnings)
    Image.new("RGB", (4, 4), (255, 0, 0)).save(world.parent / "skin.png")
    _, _, second = world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 2 and second.model.ntex == 1


def test_a_remote_texture_that_reaches_the_asset_cache_later_is_seen(cache, world, tmp_path, monkeypatch):
    monkeypatch.setenv("WBTC_ASSET_CACHE", str(tmp_path / "assets"))
    _touch_later(world, WORLD.replace('"skin.png"', '"webots://textures/skin.png"'))
    loads = _loads(monkeypatch)
    _, _, first = world_cache.load_and_compile(world, CompileOptions())
    assert first.model.ntex == 0 and any("webots://textures/skin.png" in w.message for w in first.warnings)
    # As a later run on a machine with a network would have downloaded it:
    target = tmp_path / "assets" / "raw.githubusercontent.com" / "cyberbotics" / "webots" / "R2025a" / "textures"
    target.mkdir(parents=True)
    Image.new("RGB", (4, 4), (255, 0, 0)).save(target / "skin.png")
    _, _, second = world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 2 and second.model.ntex == 1


def test_a_proto_added_to_the_project_is_found(cache, world, monkeypatch):
    loads = _loads(monkeypatch)
    (world.parent / "protos" / "Thing.proto").unlink()
    _, expansion, _ = world_cache.load_and_compile(world, CompileOptions())
    assert expansion.counts == {"Thing": 1} and expansion.sources["Thing"] is None  # unresolved, dropped
    # Put in a sub-folder of the project's protos/ (searched recursively): the folder's time changed.
    (world.parent / "protos" / "sub").mkdir()
    (world.parent / "protos" / "sub" / "Thing.proto").write_text(THING, encoding="utf-8")
    _, expansion, _ = world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 2 and expansion.sources["Thing"] is not None


def test_random_protos_are_never_cached(cache, tmp_path, monkeypatch):
    (tmp_path / "protos").mkdir()
    (tmp_path / "protos" / "Random.proto").write_text(RANDOM, encoding="utf-8")
    path = tmp_path / "random.wbt"
    path.write_text("#VRML_SIM R2022a utf8\nWorldInfo { }\nRandom { }\n", encoding="utf-8")
    loads = _loads(monkeypatch)
    world_cache.load_and_compile(path, CompileOptions())
    world_cache.load_and_compile(path, CompileOptions())
    assert len(loads) == 2 and not list(cache.glob("*.pickle"))


def test_the_spec_of_a_cached_result_is_compiled_again_on_demand(cache, world):
    _, _, first = world_cache.load_and_compile(world, CompileOptions())
    _, _, second = world_cache.load_and_compile(world, CompileOptions())
    assert second.built_spec is None
    assert second.spec.to_xml() == first.spec.to_xml()
    assert [g.info for g in second.spec.geoms] == [g.info for g in first.spec.geoms]


def test_a_damaged_entry_is_ignored_and_replaced(cache, world, monkeypatch):
    loads = _loads(monkeypatch)
    world_cache.load_and_compile(world, CompileOptions())
    (entry,) = cache.glob("*.pickle")
    entry.write_bytes(b"not a pickle")
    _, _, result = world_cache.load_and_compile(world, CompileOptions())
    assert len(loads) == 2 and result.model.nbody > 1
    assert world_cache.stamps_of(entry)  # written anew


def test_a_run_from_the_cache_loads_neither_expander_nor_compiler(cache, world):
    """Start-up: preparing a cached world in a fresh interpreter leaves the compile stage unloaded."""
    import subprocess
    import sys

    script = (
        "import sys\nfrom pathlib import Path\nfrom wbtc.runtime.launch import prepare\n"
        f"prepare(Path({str(world)!r}))\n"
        "print(sorted(m for m in sys.modules if m.startswith('wbtc.')))\n"
    )
    env = {**os.environ, "MUJOCO_GL": "disable"}
    first = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, check=True)
    assert "'wbtc.compile.compiler'" in first.stdout  # the first run compiles
    again = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, check=True)
    loaded = set(eval(again.stdout))  # noqa: S307 - our own script's printed list
    unloaded = {"wbtc.compile.compiler", "wbtc.compile.solid", "wbtc.compile.geometry", "wbtc.pipeline",
                "wbtc.scene.build", "wbtc.proto.expand", "wbtc.runtime.supervisor",
                "wbtc.runtime.scene_ops", "wbtc.runtime.overrides"}
    assert loaded & unloaded == set()
    assert {"wbtc.compile.result", "wbtc.runtime.simulation", "wbtc.scene.model"} <= loaded
