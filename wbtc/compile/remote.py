"""`webots://` and `http(s)://` asset URLs (textures, meshes) to local files, as Webots finds them.

What it maps: a url entry that names no local file ->

* `webots://PATH` (and `https://raw.githubusercontent.com/cyberbotics/webots/TAG/PATH`) ->
  `$WEBOTS_HOME/PATH` when a Webots installation (or a checkout of Webots' repository) is named by
  `WEBOTS_HOME` and holds it, as Webots reads its own installation first;
* otherwise a copy in wbtc's asset cache, downloaded once from Webots' repository at the release wbtc
  follows (`webots://PATH` -> `https://raw.githubusercontent.com/cyberbotics/webots/R2025a/PATH`, as
  a Webots without that asset installed downloads it from its own release), and any `http(s)://` URL
  from where it points. The cache is `WBTC_ASSET_CACHE`, else `$XDG_CACHE_HOME/wbtc/assets` (or
  `~/.cache/wbtc/assets`).

`WBTC_OFFLINE=1` never downloads (the cache and `WEBOTS_HOME` are still read); `WBTC_WEBOTS_URL`
replaces the address `webots://` stands for (a mirror). A download that fails is tried once per run,
and once one fails for want of a network no other is tried: the caller warns and goes on without the
asset, as before.

PROTO files are never fetched this way: wbtc's PROTO library stands for Webots' (`wbtc.proto.resolve`).
Not honoured yet: Webots' cache expiry (its cache keeps files for a set time; wbtc's keeps them until
removed by hand).
"""

from __future__ import annotations

import hashlib
import os
import sys
import tempfile
import urllib.error
import urllib.parse
import urllib.request
from pathlib import Path

#: The Webots release whose files `webots://` names (wbtc follows R2025a's nodes and PROTOs).
WEBOTS_URL = "https://raw.githubusercontent.com/cyberbotics/webots/R2025a/"

#: Seconds a download may take before it is given up.
TIMEOUT = 10.0

#: URLs whose download failed in this process, with why (tried once per run).
_FAILED: dict[str, str] = {}

#: Why the network is out of reach, once a download failed for want of it: later URLs are not tried, so
#: that a world with many remote assets on a machine without a network waits for one timeout, not one each.
_UNREACHABLE: list[str] = []


def is_remote(url: str) -> bool:
    """Whether a url entry names a file by a `webots://` or `http(s)://` address."""
    return url.startswith(("webots://", "http://", "https://"))


def local_copy(url: str, looked_at: list[list[str]] | None = None) -> str | None:
    """A local file holding the asset a remote url entry names, downloading it when needed.

    Args:
        url: a `webots://`, `http://` or `https://` url entry.
        looked_at: lists to append every local path looked at (found or not) to, so that a cached
            world result goes stale when the asset appears (`wbtc.world_cache`).

    Returns:
        The file's path, or None when the asset is not installed, not cached and cannot be
        downloaded (`failure(url)` then says why).
    """
    candidates = []
    installed = _installed(url)
    if installed is not None:
        candidates.append(installed)
    cached = str(cache_path(url))
    candidates.append(cached)
    for path in candidates:
        for watcher in looked_at or ():
            watcher.append(path)
        if os.path.isfile(path):
            return path
    if _download(source_url(url), Path(cached), url):
        return cached
    return None


def failure(url: str) -> str:
    """Why `local_copy(url)` gave None, in a few words."""
    return _FAILED.get(url, "not downloaded")


def source_url(url: str) -> str:
    """The address an asset is downloaded from (`webots://` stands for Webots' repository)."""
    if url.startswith("webots://"):
        base = os.environ.get("WBTC_WEBOTS_URL") or WEBOTS_URL
        return base.rstrip("/") + "/" + url[len("webots://"):].lstrip("/")
    return url


def cache_path(url: str) -> Path:
    """Where the asset of a remote URL is kept: the host and path of its address, under the cache.

    A query string gets a hash of itself appended, so two addresses never share a file.
    """
    parts = urllib.parse.urlsplit(source_url(url))
    pieces = [piece for piece in urllib.parse.unquote(parts.path).split("/") if piece not in ("", ".", "..")]
    if parts.query:
        pieces[-1:] = [f"{(pieces or ['asset'])[-1]}.{hashlib.sha1(parts.query.encode()).hexdigest()[:12]}"]
    return _cache_root() / (parts.netloc or "local") / Path(*pieces)


def _cache_root() -> Path:
    if os.environ.get("WBTC_ASSET_CACHE"):
        return Path(os.environ["WBTC_ASSET_CACHE"])
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "wbtc" / "assets"


#: The address of a file of a Webots release in its repository: the part after the tag is the path
#: within an installation.
_RELEASE_PREFIX = "https://raw.githubusercontent.com/cyberbotics/webots/"


def _installed(url: str) -> str | None:
    """The path of an asset in the Webots installation `WEBOTS_HOME` names, if any.

    A `webots://` asset, or a file of a Webots release named by its repository address (any tag: the
    installation stands for it).
    """
    home = os.environ.get("WEBOTS_HOME")
    if not home:
        return None
    if url.startswith("webots://"):
        relative = url[len("webots://"):]
    elif url.startswith(_RELEASE_PREFIX) and "/" in url[len(_RELEASE_PREFIX):]:
        relative = url[len(_RELEASE_PREFIX):].split("/", 1)[1]
    else:
        return None
    return os.path.normpath(os.path.join(home, relative.lstrip("/")))


def _download(address: str, target: Path, url: str) -> bool:
    """Fetch `address` into `target` atomically; False (and the reason kept) when it fails."""
    if url in _FAILED:
        return False
    if os.environ.get("WBTC_OFFLINE", "") not in ("", "0"):
        _FAILED[url] = "WBTC_OFFLINE is set"
        return False
    if _UNREACHABLE:
        _FAILED[url] = _UNREACHABLE[0]
        return False
    try:
        with urllib.request.urlopen(address, timeout=TIMEOUT) as response:  # noqa: S310 - http(s) only
            data = response.read()
        _store(data, target)
    except (OSError, ValueError, urllib.error.URLError) as exc:
        _FAILED[url] = _reason(exc)
        if isinstance(exc, (urllib.error.URLError, TimeoutError)) and not isinstance(exc, urllib.error.HTTPError):
            _UNREACHABLE.append(_FAILED[url])
        return False
    print(f"wbtc: downloaded {address} ({len(data):,} bytes) into {target}", file=sys.stderr)
    return True


def _store(data: bytes, target: Path) -> None:
    """Write beside the target and rename, so that a run stopped mid-way leaves no partial asset."""
    target.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=target.parent, prefix=".part-")
    try:
        with os.fdopen(handle, "wb") as out:
            out.write(data)
        os.replace(temporary, target)
    except OSError:
        Path(temporary).unlink(missing_ok=True)
        raise


def _reason(exc: BaseException) -> str:
    if isinstance(exc, urllib.error.HTTPError):
        return f"HTTP {exc.code} {exc.reason}"
    if isinstance(exc, urllib.error.URLError):
        return f"no network ({exc.reason})"
    return f"{type(exc).__name__}: {exc}"
