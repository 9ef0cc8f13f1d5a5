"""The `#VRML_SIM <version> utf8` header, the info comment block and Webots versions.

Versions compare as Webots compares them: `V6.0` < `V8.6` < `R2018a` < `R2020b` < `R2022a`,
revisions ignored for compatibility decisions. Old `V` versions sort before every `R` version
because their major number (6, 7, 8) is smaller than any year.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import total_ordering

from wbtc.errors import Span, WbtSyntaxError

_HEADER = re.compile(r"^#\s*VRML_SIM\s+(?P<version>.+?)\s+utf8\s*$")
_R_VERSION = re.compile(r"^R(?P<year>\d{4})(?P<letter>[a-z])(?:(?:\s+revision\s+|-rev)(?P<rev>\d+))?$")
_V_VERSION = re.compile(r"^V(?P<major>\d+)\.(?P<minor>\d+)(?:\.(?P<rev>\d+))?$")


@total_ordering
@dataclass(frozen=True, slots=True)
class Version:
    """A Webots version: R2023b is (2023, 1, 0); V8.5 is (8, 5, 0)."""

    major: int
    minor: int
    revision: int = 0
    text: str = ""

    @classmethod
    def parse(cls, text: str) -> Version | None:
        """Read `R2023b`, `R2023b revision 1`, `R2019a-rev2`, `V8.5` or `V6.0`; None if unknown."""
        text = text.strip()
        match = _R_VERSION.match(text)
        if match:
            letter = ord(match["letter"]) - ord("a")
            return cls(int(match["year"]), letter, int(match["rev"] or 0), text)
        match = _V_VERSION.match(text)
        if match:
            return cls(int(match["major"]), int(match["minor"]), int(match["rev"] or 0), text)
        return None

    def key(self) -> tuple[int, int]:
        """The part that compatibility decisions use (revisions are ignored)."""
        return (self.major, self.minor)

    def __lt__(self, other: object) -> bool:
        if not isinstance(other, Version):
            return NotImplemented
        return self.key() < other.key()

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Version):
            return NotImplemented
        return self.key() == other.key()

    def __hash__(self) -> int:
        return hash(self.key())

    def __str__(self) -> str:
        return self.text or (f"R{self.major}{chr(ord('a') + self.minor)}" if self.major > 1000
                             else f"V{self.major}.{self.minor}")


#: Webots versions at which behaviour changed.
R2020B = Version(2020, 1, 0, "R2020b")  # coordinateSystem field; NUE default before
R2022A = Version(2022, 0, 0, "R2022a")  # ENU/FLU axes; primitive axes changed
R2022B = Version(2022, 1, 0, "R2022b")  # EXTERNPROTO lines
R2023B = Version(2023, 1, 0, "R2023b")  # Pose node


def before_r2022a(version: Version | None) -> bool:
    """True for a file written with the old axes: Webots' primitives and PROTOs then stood along y.

    Webots' backward-compatibility fix (WbNodeUtilities::fixBackwardCompatibility) applies to files
    up to R2021b: "R2021c" was the development name of R2022a, whose files (Webots' own test worlds
    among them) already hold FLU objects, even in an NUE world.
    """
    return version is not None and version.key() <= (2021, 1)


def read_header(text: str, path: str) -> tuple[Version, list[str]]:
    """Check the header line and collect the info comment block.

    Args:
        text: the whole file.
        path: the file name for error spans.

    Returns:
        The version and the info lines (every leading line starting with '#', without the '#').

    Raises:
        WbtSyntaxError: the first line is not a `#VRML_SIM <version> utf8` header.
    """
    first, _, _ = text.partition("\n")
    first = first.lstrip("\ufeff").rstrip("\r")
    match = _HEADER.match(first)
    if not match:
        raise WbtSyntaxError(
            "invalid header: the first line must be '#VRML_SIM <version> utf8'",
            Span(path, 1, 1),
            hint="for example '#VRML_SIM R2025a utf8'",
        )
    version = Version.parse(match["version"])
    if version is None:
        column = first.index(match["version"]) + 1
        raise WbtSyntaxError(
            f"invalid header: unknown Webots version '{match['version']}'",
            Span(path, 1, column),
            hint="versions look like R2025a, R2023b or V8.5",
        )
    info = []
    for line in text.splitlines():
        stripped = line.strip()
        if not stripped.startswith("#"):
            break
        info.append(stripped[1:].strip())
    return version, info


def template_language(info: list[str]) -> str | None:
    """The template language an info block announces ("javascript", "lua"), or None."""
    for line in info:
        key, sep, value = line.partition(":")
        if sep and key.strip().lower() == "template language":
            value = value.strip().lower()
            return "javascript" if "javascript" in value else value or None
    return None
