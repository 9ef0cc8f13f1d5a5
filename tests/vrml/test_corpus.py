"""Every .wbt and .proto of the shared corpus parses (and every world builds a typed scene)."""

import pytest
from conftest import CORPUS, corpus_files

from wbtc.errors import WbtcError
from wbtc.scene import build_scene
from wbtc.vrml import parse_file

FILES = corpus_files(".wbt", ".proto")

#: Corpus files Webots itself refuses to load, with the error wbtc must give (line, column, message).
#: world_maze.wbt writes `name = "gps"`: Webots' parser wants a string after `name` and stops.
REJECTED = {
    "projects/Mummanajagadeesh__wall-follower-robot/worlds/world_maze.wbt": (32, 12, "'=' is not a field value"),
}


def _id(path):
    return str(path.relative_to(CORPUS))


def test_corpus_is_complete() -> None:
    assert len([f for f in FILES if f.suffix == ".wbt"]) == 158
    assert len([f for f in FILES if f.suffix == ".proto"]) == 18


@pytest.mark.parametrize("path", FILES, ids=_id)
def test_corpus_file_parses(path) -> None:
    rejected = REJECTED.get(_id(path))
    if rejected is not None:
        with pytest.raises(WbtcError) as info:
            build_scene(parse_file(path))
        diag = info.value.diagnostics[0]
        assert (diag.span.line, diag.span.column, diag.message) == rejected
        return
    syntax = parse_file(path)
    if path.suffix == ".wbt":
        scene = build_scene(syntax)
        assert scene.node_count > 0
        assert scene.coordinate_system in ("ENU", "NUE", "EUN")
    else:
        assert len(syntax.protos) == 1
        proto = syntax.protos[0]
        assert proto.fields or proto.template is not None or proto.body
        assert (proto.template is None) == bool(proto.body)
