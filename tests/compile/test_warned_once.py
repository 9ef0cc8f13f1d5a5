"""The same warning at the same place is given once, however many nodes a PROTO makes from one field."""

from pathlib import Path

from wbtc.pipeline import compile_world


def test_four_arena_walls_with_one_missing_texture_warn_once(tmp_path: Path) -> None:
    world = tmp_path / "arena.wbt"
    world.write_text('#VRML_SIM R2025a utf8\nWorldInfo { }\nRectangleArena { wallAppearance PBRAppearance {\n'
                     '  baseColorMap ImageTexture { url "missing.png" } } }\n', encoding="utf-8")
    result, _ = compile_world(world)
    missing = [w for w in result.warnings if "'missing.png' cannot be found" in w.message]
    # RectangleArena's four walls share the appearance written on line 4: it warned four times.
    assert [(w.span.line, w.span.column) for w in missing] == [(4, 16)]
