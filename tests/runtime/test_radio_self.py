"""A robot's receiver never gets its own emitter's packets (Webots), another robot's does."""

from pathlib import Path

from wbtc.pipeline import compile_world
from wbtc.runtime.devices import Emitter, Receiver
from wbtc.runtime.simulation import Simulation

FIXTURE = Path(__file__).parent / "fixtures" / "self_radio.wbt"


def test_a_robot_does_not_hear_itself_but_the_other_robot_does():
    result, _ = compile_world(FIXTURE)
    sim = Simulation(result, noise=False)
    talker, listener = sim.robots
    emitter = next(e for e in talker.emitters.values() if isinstance(e, Emitter))
    own = next(s for s in talker.sensors.values() if isinstance(s, Receiver))
    other = next(s for s in listener.sensors.values() if isinstance(s, Receiver))
    own.period = other.period = 32
    sim.packets.append((emitter, b"hello", emitter.channel))
    sim.step()
    assert own.incoming == []
    assert [packet[:2] for packet in other.incoming] == [(b"hello", 1)]


def test_packets_of_several_periods_wait_together_for_the_controller():
    result, _ = compile_world(FIXTURE)
    sim = Simulation(result, noise=False)
    talker, listener = sim.robots
    emitter = next(e for e in talker.emitters.values() if isinstance(e, Emitter))
    other = next(s for s in listener.sensors.values() if isinstance(s, Receiver))
    other.enable(32, sim.time_ms)
    for word in (b"one", b"two", b"three"):  # a controller's step(96): three periods, one reply
        sim.packets.append((emitter, word, emitter.channel))
        sim.step()
    assert other.fresh and [packet[0] for packet in other.value] == [b"one", b"two", b"three"]
