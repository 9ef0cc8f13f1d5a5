"""Where wbtc's data lives: `grammars/` and `protos/`.

In a source checkout they sit at the top of the repository; in an installed wheel they ship as the
data packages `wbtc._grammars` and `wbtc._protos` (see pyproject.toml).
"""

from __future__ import annotations

import importlib.util
from functools import cache
from pathlib import Path

_CHECKOUT = Path(__file__).resolve().parent.parent


@cache
def _data_dir(folder: str, package: str) -> Path:
    spec = importlib.util.find_spec(package)
    if spec is not None and spec.submodule_search_locations:
        return Path(next(iter(spec.submodule_search_locations)))
    return _CHECKOUT / folder


def grammar_path(name: str) -> Path:
    """The path of a grammar file shipped with wbtc."""
    local = _CHECKOUT / "grammars" / name
    return local if local.exists() else _data_dir("grammars", "wbtc._grammars") / name


def protos_dir() -> Path:
    """The folder of wbtc's own PROTO library."""
    local = _CHECKOUT / "protos"
    return local if local.is_dir() else _data_dir("protos", "wbtc._protos")


def child_path() -> Path:
    """The folder put first on a controller process's PYTHONPATH (it holds the `controller` package)."""
    return Path(__file__).resolve().parent / "_child"
