"""PROTO expansion speed: parse + typed scene + PROTO expansion of the largest corpus world (goal: under 2 s).

Prints three figures for the whole front of the pipeline (what `wbtc check` does before its report):

* first run: a fresh process, so it includes loading the grammar, starting the JavaScript engine and
  compiling the template modules;
* fresh caches, best of several runs: PROTO files re-read and every template rendered again each run
  (the cost of one more world in a warm process; the figure checked against the goal);
* warm caches, best of several runs: PROTO models and rendered template text reused.

Run: python bench/expand.py [WORLD]
"""

import sys
import time
from pathlib import Path

from timing import best_of, largest_world

from wbtc.proto import expand
from wbtc.proto.expand import expand_scene
from wbtc.proto.model import load_proto
from wbtc.scene import build_scene
from wbtc.vrml import parse_file

GOAL_S = 2.0


def clear_caches() -> None:
    # The PROTO stage keeps parsed PROTO files and rendered template text for the life of the process.
    load_proto.cache_clear()
    expand._RENDERED.clear()


def front(world: Path) -> tuple[float, int]:
    """Seconds for parse + scene + expansion, and the PROTO instances written in the world."""
    start = time.perf_counter()
    _scene, expansion = expand_scene(build_scene(parse_file(world)))
    return time.perf_counter() - start, sum(expansion.counts.values())


def main() -> None:
    if len(sys.argv) > 1:
        world = Path(sys.argv[1])
    else:
        world = largest_world()
    first_s, instances = front(world)
    fresh_s = best_of(lambda: front(world), before=clear_caches)
    warm_s = best_of(lambda: front(world))
    print(f"world: {world.name} ({world.stat().st_size / 1e6:.2f} MB, {instances} PROTO instances)")
    print(f"first run (cold process):   {first_s * 1000:8.1f} ms")
    print(f"fresh caches, best of 5:    {fresh_s * 1000:8.1f} ms")
    print(f"warm caches, best of 5:     {warm_s * 1000:8.1f} ms")
    print(f"goal {GOAL_S:.0f} s: {'met' if fresh_s <= GOAL_S else 'NOT met'} ({GOAL_S / fresh_s:.0f}x margin)")


if __name__ == "__main__":
    main()
