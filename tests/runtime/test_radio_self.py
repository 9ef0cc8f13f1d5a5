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


IR_WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 32
}
Robot {
  children [
    Emitter {
      type "infra-red"
      channel 1
    }
  ]
  name "sender"
  boundingObject Box {
    size 0.2 0.2 0.2
  }
}
Robot {
  translation 1 0 0
  rotation 0 0 1 3.14159
  children [
    Receiver {
      type "infra-red"
      channel 1
    }
  ]
  name "listener"
  boundingObject Box {
    size 0.2 0.2 0.2
  }
}
"""


def test_an_infra_red_emitter_inside_its_robot_still_reaches_a_receiver_in_sight(tmp_path):
    world = tmp_path / "ir.wbt"
    world.write_text(IR_WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    sender, listener = sim.robots
    emitter = next(iter(sender.emitters.values()))
    receiver = next(s for s in listener.sensors.values() if isinstance(s, Receiver))
    receiver.enable(32, sim.time_ms)
    sim.packets.append((emitter, b"seen", emitter.channel))
    sim.step()
    assert [packet[0] for packet in receiver.value] == [b"seen"]
