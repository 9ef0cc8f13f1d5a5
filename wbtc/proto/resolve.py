"""Find the file of a PROTO, never over the network.

Order, as Webots looks (and as old worlds without EXTERNPROTO lines need):

1. a PROTO declared in the same file;
2. an EXTERNPROTO line of the file naming it: a relative path (relative to the declaring file), an
   absolute path, or a `webots://...` / `https://raw.githubusercontent.com/cyberbotics/webots/<tag>/...`
   URL, which maps to wbtc's library by PROTO name (a relative file that is missing also falls
   back to the library by name);
3. the world's project: the `protos/` folders Webots searches, beside and above the world's folder
   (recursively, as a Webots project's `protos/` may hold sub-folders);
4. wbtc's own library (`protos/` of this package).

Not honoured yet: other `https://` hosts (resolved by file name in the library only) and Webots'
extra project paths (`WEBOTS_EXTRA_PROJECT_PATH`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from wbtc.resources import protos_dir
from wbtc.vrml import syntax as s


@dataclass(frozen=True, slots=True)
class ProtoSource:
    """Where a PROTO name resolved: a file, and how it was found."""

    name: str
    path: Path
    how: str  # "extern", "project", "library"

    @property
    def label(self) -> str:
        """What `wbtc check` shows: the path, or "wbtc:NAME" for the library."""
        return f"wbtc:{self.name}" if self.how == "library" else str(self.path)


@lru_cache(maxsize=1)
def library_index() -> dict[str, Path]:
    """Wbtc's own PROTOs by name (file stem)."""
    index: dict[str, Path] = {}
    for path in sorted(protos_dir().rglob("*.proto")):
        index.setdefault(path.stem, path)
    return index


@lru_cache(maxsize=64)
def _project_index(folder: Path) -> dict[str, Path]:
    index: dict[str, Path] = {}
    for path in sorted(folder.rglob("*.proto")):
        index.setdefault(path.stem, path)
    return index


def project_proto_dirs(world_path: Path) -> list[Path]:
    """The `protos/` folders searched for a world: beside its folder and in every folder above it.

    For `PROJECT/worlds/w.wbt` that is `PROJECT/worlds/protos`, `PROJECT/protos`, and so on up, but
    never above the user's home or the file system root's first level.
    """
    folders = []
    folder = world_path.resolve().parent
    for _ in range(4):
        candidate = folder / "protos"
        if candidate.is_dir():
            folders.append(candidate)
        if folder.parent == folder:
            break
        folder = folder.parent
    return folders


def _url_name(url: str) -> str:
    return url.replace("\\", "/").rsplit("/", 1)[-1].rsplit(".", 1)[0]


class Resolver:
    """Resolves PROTO names for one file (a world or a PROTO), given the world it belongs to."""

    def __init__(self, file_path: Path, externprotos: list[s.ExternProto], world_path: Path) -> None:
        self.file_path = file_path
        self.world_path = world_path
        self.externs: dict[str, s.ExternProto] = {}
        for extern in externprotos:
            self.externs.setdefault(_url_name(extern.url), extern)

    def resolve(self, name: str) -> ProtoSource | None:
        """The file of PROTO `name`, or None when no place has it."""
        extern = self.externs.get(name)
        if extern is not None:
            found = self._from_url(name, extern.url)
            if found is not None:
                return found
        for folder in project_proto_dirs(self.world_path):
            path = _project_index(folder).get(name)
            if path is not None:
                return ProtoSource(name, path, "project")
        # A PROTO file's own folder: Webots finds sibling PROTOs of a PROTO declared by name.
        sibling = self.file_path.parent / f"{name}.proto"
        if self.file_path.suffix == ".proto" and sibling.is_file():
            return ProtoSource(name, sibling, "project")
        path = library_index().get(name)
        return ProtoSource(name, path, "library") if path is not None else None

    def _from_url(self, name: str, url: str) -> ProtoSource | None:
        lowered = url.lower()
        if lowered.startswith(("webots://", "https://", "http://")):
            path = library_index().get(name)
            return ProtoSource(name, path, "library") if path is not None else None
        local = Path(url)
        if not local.is_absolute():
            local = self.file_path.parent / local
        if local.is_file():
            return ProtoSource(name, local, "extern")
        path = library_index().get(name)
        return ProtoSource(name, path, "library") if path is not None else None

    def searched(self, name: str) -> list[str]:
        """The places searched for `name`, for the message of an unresolved PROTO."""
        places = []
        if name in self.externs:
            places.append(f'EXTERNPROTO "{self.externs[name].url}"')
        places += [str(d) for d in project_proto_dirs(self.world_path)]
        places.append("wbtc's PROTO library")
        return places
