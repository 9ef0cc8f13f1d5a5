"""Every corpus world expands; the PROTOs left unresolved are listed with a reason and stay rare."""

from collections import Counter
from pathlib import Path

import pytest
from conftest import CORPUS, corpus_files

from wbtc.proto.expand import expand_scene
from wbtc.scene import build_scene
from wbtc.vrml import parse_file

WORLDS = [w for w in corpus_files(".wbt") if "world_maze.wbt" not in w.name]  # Webots rejects it too
LISTED = {}
for line in (Path(__file__).parent / "unresolved.txt").read_text().splitlines():
    if line.strip() and not line.startswith("#"):
        name, _, reason = line.partition(" ")
        LISTED[name] = reason.strip()

_TOTALS: Counter[str] = Counter()
_UNRESOLVED: Counter[str] = Counter()
_MISSING: set[str] = set()


@pytest.mark.parametrize("world", WORLDS, ids=lambda p: str(p.relative_to(CORPUS)))
def test_corpus_world_expands(world) -> None:
    scene, expansion = expand_scene(build_scene(parse_file(world)))
    assert all(not node.is_proto for node in scene.walk())
    for name, count in expansion.counts.items():
        _TOTALS[name] += count
        if expansion.sources.get(name) is None:
            _UNRESOLVED[name] += count
    missing = {n for n, src in expansion.sources.items() if src is None}
    _MISSING.update(missing)
    assert missing <= set(LISTED), f"unresolved and not listed in tests/proto/unresolved.txt: {missing - set(LISTED)}"


def test_unresolved_instances_stay_under_ten_percent() -> None:
    # Issue 3: at most 10 % of the PROTO instances may stay unresolved. The Erebus rescue-maze tiles and
    # markers (worldTile, halfTile, Victim, HazardMap: 329 instances), TinkerbotsBase (43), UR5e (20),
    # SickLms291 (3), Mavic2Pro (1), Pioneer2, CreateWall, LinkedWalls, LargeValve, SmallValve, Irb4600-40 and
    # the three robotbenchmark robots (1 each) now come from wbtc's library; what is left is listed in
    # unresolved.txt. Irb4600-40 resolving also counts the two BrushedAluminium instances its world writes
    # inside the arm's handSlot (3,284 -> 3,286).
    # The exact count
    # makes any change (better or worse) show up here.
    if not _TOTALS:  # run alone: expand the corpus here
        for world in WORLDS:
            test_corpus_world_expands(world)
    total, unresolved = sum(_TOTALS.values()), sum(_UNRESOLVED.values())
    assert total == 3286
    assert unresolved == 2, f"{unresolved}/{total} PROTO instances unresolved: {_UNRESOLVED.most_common()}"
    assert unresolved / total <= 0.10
    assert _MISSING == set(LISTED), "tests/proto/unresolved.txt lists a PROTO that now resolves"
