"""protos/README.md documents every PROTO of the library, and its generator still runs."""

from __future__ import annotations

import importlib.util
import re
import sys

from conftest import REPO

SCRIPT = REPO / "protos" / "make_readme.py"


def load_generator():
    spec = importlib.util.spec_from_file_location("make_readme", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def test_readme_lists_every_library_proto() -> None:
    readme = (REPO / "protos" / "README.md").read_text(encoding="utf-8")
    folders = "robots|vehicles|humans|devices|objects|joints|appearances"
    listed = set(re.findall(rf"^\| \[?([\w+-]+)\]?(?:\(#[\w-]+\))? \| (?:{folders}) \|", readme, re.M))  # "Tiago++"
    names = {path.stem for path in (REPO / "protos").rglob("*.proto")}
    assert names == listed, "protos/README.md is out of date: run python protos/make_readme.py"


def test_generator_runs_and_documents_devices() -> None:
    text = load_generator().generate()
    assert "| `groundSensorsSlot` | MFNode | `[]` |" in text
    assert "| ps0 | DistanceSensor | 0.03 -0.01 0.033 |" in text
    assert "With `version \"2\"`: adds tof (DistanceSensor)." in text
    assert "### worldTile" in text
