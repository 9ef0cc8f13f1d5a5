"""Reading Webots VRML text: header, grammar, syntax tree."""

from wbtc.vrml.header import Version, read_header
from wbtc.vrml.parser import parse_file, parse_text, parse_value

__all__ = ["Version", "parse_file", "parse_text", "parse_value", "read_header"]
