"""Remote assets: `webots://` and `http(s)://` urls through a Webots installation, the cache or a download.

Downloads go to a real HTTP server on this machine, standing for raw.githubusercontent.com.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.conftest import serving, simulation_of
from wbtc.compile import remote

PNG_RED = bytes.fromhex(
    "89504e470d0a1a0a0000000d4948445200000002000000020802000000fdd49a730000001049444154789c63f8cfc0"
    "00440c100a001fee03fd8b5f14d40000000049454e44ae426082"
)  # a 2x2 red PNG


@pytest.fixture
def server(tmp_path: Path) -> Iterator[tuple[str, Path, list[str]]]:
    """An HTTP server on 127.0.0.1 serving `tmp_path/site`: (base URL, its folder, the paths asked for)."""
    site = tmp_path / "site"
    site.mkdir()
    with serving(site) as (port, asked):
        yield f"http://127.0.0.1:{port}/R2025a/", site, asked


@pytest.fixture
def online(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Downloads allowed, an empty asset cache of the test's own (returned), no failures remembered."""
    cache = tmp_path / "cache"
    monkeypatch.delenv("WBTC_OFFLINE", raising=False)
    monkeypatch.setenv("WBTC_ASSET_CACHE", str(cache))
    monkeypatch.setattr(remote, "_FAILED", {})
    monkeypatch.setattr(remote, "_UNREACHABLE", [])
    return cache


def test_webots_url_downloaded_once_then_cached(server, online: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    base, site, asked = server
    (site / "R2025a" / "textures").mkdir(parents=True)
    (site / "R2025a" / "textures" / "red.png").write_bytes(PNG_RED)
    monkeypatch.setenv("WBTC_WEBOTS_URL", base)
    port = base.split(":")[2].split("/")[0]
    path = remote.local_copy("webots://textures/red.png")
    assert path == str(online / f"127.0.0.1:{port}" / "R2025a" / "textures" / "red.png")
    assert Path(path).read_bytes() == PNG_RED
    assert asked == ["/R2025a/textures/red.png"]
    assert remote.local_copy("webots://textures/red.png") == path
    assert len(asked) == 1  # the second look finds the cached copy
    assert [p.name for p in Path(path).parent.iterdir()] == ["red.png"]  # no partial file left


def test_default_address_is_webots_release() -> None:
    assert remote.source_url("webots://projects/default/worlds/textures/stone.jpg") == (
        "https://raw.githubusercontent.com/cyberbotics/webots/R2025a/projects/default/worlds/textures/stone.jpg")
    assert remote.source_url("https://example.org/a/b.png") == "https://example.org/a/b.png"


def test_query_strings_get_their_own_file(online: Path) -> None:
    first = remote.cache_path("https://example.org/m/mesh.obj?v=1")
    second = remote.cache_path("https://example.org/m/mesh.obj?v=2")
    assert first.parent == second.parent == online / "example.org" / "m"
    assert first.name.startswith("mesh.obj.") and first != second
    assert remote.cache_path("https://example.org/../../etc/passwd") == online / "example.org" / "etc" / "passwd"


def test_failed_download_tried_once(server, online: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    base, _, asked = server
    monkeypatch.setenv("WBTC_WEBOTS_URL", base)
    assert remote.local_copy("webots://textures/missing.png") is None
    assert remote.failure("webots://textures/missing.png") == "HTTP 404 File not found"
    assert remote.local_copy("webots://textures/missing.png") is None
    assert len(asked) == 1
    assert not any(online.rglob("*missing*"))


def test_offline_and_webots_home(tmp_path: Path, online: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("WBTC_OFFLINE", "1")
    assert remote.local_copy("webots://textures/red.png") is None
    assert remote.failure("webots://textures/red.png") == "WBTC_OFFLINE is set"
    home = tmp_path / "webots"
    (home / "textures").mkdir(parents=True)
    (home / "textures" / "red.png").write_bytes(PNG_RED)
    monkeypatch.setenv("WEBOTS_HOME", str(home))
    looked_at: list[str] = []
    assert remote.local_copy("webots://textures/red.png", [looked_at]) == str(home / "textures" / "red.png")
    assert looked_at == [str(home / "textures" / "red.png")]
    # A release's repository address stands for the same file of the installation, whatever its tag.
    release = "https://raw.githubusercontent.com/cyberbotics/webots/R2022b/textures/red.png"
    assert remote.local_copy(release) == str(home / "textures" / "red.png")


WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Solid {
  children [ Shape { appearance Appearance { texture ImageTexture { url [ "webots://textures/red.png" ] } }
                     geometry Box { size 1 1 1 } } ]
}
"""


def test_world_texture_from_download(server, online: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    base, site, _ = server
    (site / "R2025a" / "textures").mkdir(parents=True)
    (site / "R2025a" / "textures" / "red.png").write_bytes(PNG_RED)
    monkeypatch.setenv("WBTC_WEBOTS_URL", base)
    simulation = simulation_of(tmp_path, WORLD)
    try:
        model = simulation.model
        assert model.ntex == 1 and model.tex_width[0] == 2 and model.tex_height[0] == 2
        assert model.tex_data[:3].tolist() == [255, 0, 0]
    finally:
        simulation.close()


def test_world_texture_offline_warns(tmp_path: Path, online: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from wbtc.pipeline import compile_world

    monkeypatch.setenv("WBTC_OFFLINE", "1")
    world = tmp_path / "w.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    assert [w.message for w in result.warnings if "texture" in w.message] == [
        "the texture 'webots://textures/red.png' cannot be found (WBTC_OFFLINE is set); the shape keeps its "
        "plain colour"]


def test_no_network_is_tried_once(online: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # A port nothing listens on: the connection is refused, as a machine without a network fails.
    monkeypatch.setenv("WBTC_WEBOTS_URL", "http://127.0.0.1:9/R2025a/")
    tried: list[str] = []
    real = remote.urllib.request.urlopen

    def counting(address: str, timeout: float):
        tried.append(address)
        return real(address, timeout=timeout)

    monkeypatch.setattr(remote.urllib.request, "urlopen", counting)
    assert remote.local_copy("webots://a.png") is None and remote.local_copy("webots://b.png") is None
    assert tried == ["http://127.0.0.1:9/R2025a/a.png"]
    assert remote.failure("webots://a.png").startswith("no network (")
    assert remote.failure("webots://b.png") == remote.failure("webots://a.png")
