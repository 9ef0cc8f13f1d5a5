"""World files whose bytes are not all UTF-8 (an é saved as Latin-1): read as Webots reads them, with a warning.

Webots reads .wbt and .proto files as UTF-8 and turns the bytes that are not into U+FFFD; wbtc refused
the whole world ("cannot read ...: 'utf-8' codec can't decode byte 0xe9").
"""

from pathlib import Path

from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.vrml import parse_file

_WORLD = '#VRML_SIM R2023b utf8\nWorldInfo { basicTimeStep 16 }\nSolid { name "caf\u00e9" }\n'


def test_a_latin1_byte_is_read_as_the_replacement_character(tmp_path: Path) -> None:
    world = tmp_path / "latin1.wbt"
    world.write_bytes(_WORLD.encode("latin-1"))
    syntax = parse_file(world)
    assert [(w.message, w.span.line, w.span.column) for w in syntax.warnings] == [
        ("byte 0xe9 is not UTF-8 (the file may be Latin-1): it and the other such bytes are read as U+FFFD, as "
         "Webots reads them", 3, 18)]
    assert 'name "caf\ufffd"' in syntax.text
    # `wbtc run` runs it and says so, at the byte.
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.1"])
    assert result.exit_code == 0, result.output
    assert f"{world}:3:18: warning: byte 0xe9 is not UTF-8" in result.stderr


def test_utf8_with_a_byte_order_mark_reads_without_a_warning(tmp_path: Path) -> None:
    world = tmp_path / "bom.wbt"
    world.write_bytes(b"\xef\xbb\xbf" + _WORLD.encode("utf-8"))
    syntax = parse_file(world)
    assert syntax.warnings == []
    assert syntax.text.startswith("#VRML_SIM")
