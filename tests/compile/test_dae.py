"""COLLADA meshes (Mesh url "*.dae") load through trimesh and pycollada."""

from pathlib import Path

import pytest
import trimesh

from wbtc.pipeline import compile_world


def test_dae_mesh_is_a_geom_and_its_volume_gives_the_mass(tmp_path: Path):
    box = trimesh.creation.box((0.2, 0.2, 0.2))
    (tmp_path / "box.dae").write_bytes(trimesh.exchange.dae.export_collada(box))
    (tmp_path / "world.wbt").write_text(
        '#VRML_SIM R2023b utf8\nSolid {\n  children [ Shape { geometry Mesh { url "box.dae" } } ]\n'
        '  boundingObject Mesh { url "box.dae" }\n  physics Physics { density 1000 }\n}\n', encoding="utf-8")
    result, _ = compile_world(tmp_path / "world.wbt")
    assert result.model.ngeom == 2
    assert result.model.body_mass[1] == pytest.approx(8.0, rel=1e-6)
    assert not result.warnings
