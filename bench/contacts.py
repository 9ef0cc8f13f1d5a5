"""Contacts: what `--ode-contacts` costs per basic step, against wbtc's default contact, side by side.

Steps the workshop's Example 5 world (an e-puck driving at a box, 32 ms steps, 2 ms substeps) with
wbtc's default contact, with `--ode-contacts`, and with `--ode-contacts` but without its bounce
(the split substeps that look for landings), and prints microseconds per basic step and the ratios.
No goal: the option is opt-in; the figures say what it costs (README, Contacts).
Run: python bench/contacts.py [STEPS]
"""

import sys

from timing import REPO, best_of

from wbtc.runtime.launch import prepare

WORLD = REPO / "worlds" / "ex05_obstacle_led.wbt"


def per_step(ode: bool, bounce: bool, steps: int) -> float:
    """Best of 6 timings of `steps` basic steps (after 50 untimed), in microseconds per step."""
    sim = prepare(WORLD, ode_contacts=ode).sim
    if not bounce:
        sim.table.bounce = None  # the option's soft rows and friction, without looking for landings
    for _ in range(50):
        sim.step()

    def run() -> None:
        for _ in range(steps):
            sim.step()

    return best_of(run, runs=6) / steps * 1e6


def main() -> None:
    steps = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    default = per_step(False, False, steps)
    ode = per_step(True, True, steps)
    soft_only = per_step(True, False, steps)
    print(f"{WORLD.name}, {steps} steps of 32 ms (16 substeps each), best of 6:")
    print(f"  default contact:                {default:7.0f} us per step")
    print(f"  --ode-contacts:                 {ode:7.0f} us per step ({ode / default:.2f}x the default)")
    print(f"  --ode-contacts without bounce:  {soft_only:7.0f} us per step ({soft_only / default:.2f}x the default)")


if __name__ == "__main__":
    main()
