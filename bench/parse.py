"""Parse speed: lines per second for the largest corpus world (goal: 50,000 lines/s on one core).

Prints the figure for the syntax stage alone and for syntax + typed scene, best of several runs.
Run: python bench/parse.py [WORLD]
"""

import sys
from pathlib import Path

from timing import best_of, largest_world

from wbtc.scene import build_scene
from wbtc.vrml import parse_file, parse_text


def main() -> None:
    if len(sys.argv) > 1:
        world = Path(sys.argv[1])
    else:
        world = largest_world()
    text = world.read_text(encoding="utf-8")
    lines = text.count("\n") + 1
    parse_file(world)  # warm up: grammar tables loaded once per process
    parse_s = best_of(lambda: parse_text(text, str(world)))
    scene_s = best_of(lambda: build_scene(parse_text(text, str(world))))
    print(f"world: {world.name} ({len(text) / 1e6:.2f} MB, {lines} lines)")
    megabytes = len(text) / 1e6
    print(f"parse:         {parse_s * 1000:8.1f} ms  {lines / parse_s:10.0f} lines/s  {megabytes / parse_s:6.1f} MB/s")
    print(f"parse + scene: {scene_s * 1000:8.1f} ms  {lines / scene_s:10.0f} lines/s  {megabytes / scene_s:6.1f} MB/s")
    print(f"goal 50,000 lines/s: {'met' if lines / scene_s >= 50_000 else 'NOT met'} "
          f"(ratio {lines / scene_s / 50_000:.2f}x)")


if __name__ == "__main__":
    main()
