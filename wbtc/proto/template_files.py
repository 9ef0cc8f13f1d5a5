"""What templates see of the run beyond their fields: its temporary folder, and which generation it is.

- `context.temporary_files_path`: Webots gives each of its runs a fresh temporary folder, so a file a
  template writes there (a count of its regenerations) starts anew with the run; wbtc makes one per
  process when a template first uses it and removes it at exit (`wbtc run` calls
  `remove_temporary_files` before its quick exit).
- Outside inputs: a template that reads or writes files makes text that no cache may keep.
- Generations: a PROTO tagged `nonDeterministic` is generated anew at each simulation reset; the
  expander keys its rendered text by `generation()`, which `regenerate_non_deterministic` advances.
"""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile

_TEMPORARY: list[str] = []
_GENERATION = [0]
_OUTSIDE_INPUTS = [0]


def note_outside_input() -> None:
    """Say that a template's text now depends on more than its fields (files it read or wrote)."""
    _OUTSIDE_INPUTS[0] += 1


def outside_inputs() -> int:
    """How many times templates have used files so far (`wbtc.world_cache` caches no such world)."""
    return _OUTSIDE_INPUTS[0]


def regenerate_non_deterministic() -> None:
    """Make the next expansions generate nonDeterministic PROTOs anew (a simulation reset)."""
    _GENERATION[0] += 1


def temporary_files_path() -> str:
    """The folder of this process for templates' files (`context.temporary_files_path`, ending in /).

    Webots gives each of its runs a fresh temporary folder, so a file a template writes there (a count
    of its regenerations) starts anew with the run; the folder goes when the process ends.
    """
    note_outside_input()
    if not _TEMPORARY:
        folder = tempfile.mkdtemp(prefix="wbtc-templates-")
        atexit.register(remove_temporary_files)
        _TEMPORARY.append(folder + os.sep)
    return _TEMPORARY[0]


def remove_temporary_files() -> None:
    """Remove the templates' temporary folder (at exit; `wbtc run` calls it before its quick exit)."""
    while _TEMPORARY:
        shutil.rmtree(_TEMPORARY.pop(), ignore_errors=True)


def generation() -> int:
    """How many resets have asked for nonDeterministic PROTOs anew."""
    return _GENERATION[0]
