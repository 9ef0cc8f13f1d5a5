"""Supervisor of the two-wheel-robot world (a Robot with supervisor TRUE).
Lesson: move the node DEF Obstacle to a first position, let UP/DOWN keys brighten/dim the light
DEF light (its pointLightIntensity field), show two labels (the last key, the frame counter), and
at frame 300 move the obstacle into the robot's way. The positions below were written for that
lesson's world (y-up); a wbtc world shipped for this lesson uses its own positions."""
from controller import Robot, Supervisor

supervisor = Supervisor()
timestep = int(supervisor.getBasicTimeStep())

obstacle = supervisor.getFromDef("Obstacle")
obstacle_pos = obstacle.getField("translation")

# The lesson's line: `obs_centre_pos = [-2.68744,  0.199608, -0.831638]`. The lesson's positions are
# for its own world, whose y axis points up; wbtc's two_wheels.wbt is z-up (ENU) with its own layout:
# the obstacle (a 10 cm box) first goes off the robot's path, ...
obs_centre_pos = [-0.3, 0.45, 0.05]
# The lesson's line: `obs_en_router = [-2.719, 0.152944, 0.397579]`. ... and at frame 300 onto the
# robot's path, 0.55 m ahead of its start (x = 0.1) in two_wheels.wbt:
obs_en_router = [0.65, 0.0, 0.05]

light = supervisor.getFromDef("light")
light_intensity = light.getField("pointLightIntensity")

keyboard = supervisor.getKeyboard()
keyboard.enable(timestep)

obstacle_pos.setSFVec3f(obs_centre_pos)

loop_counter = 0
while supervisor.step(timestep) != -1:
    key = keyboard.getKey()
    if key == keyboard.UP:
        intensity = light_intensity.getSFFloat()
        light_intensity.setSFFloat(intensity + 0.1)
    elif key == keyboard.DOWN:
        intensity = light_intensity.getSFFloat()
        light_intensity.setSFFloat(intensity - 0.1)
    supervisor.setLabel(1, 'Key {}'.format(key), 0.8, 0.2, 0.1, 0x00ffff, 0.4)
    supervisor.setLabel(2, 'Frame: {}th'.format(loop_counter), 0.8, 0.1, 0.1, 0xff0000, 0.2)
    loop_counter += 1
    if loop_counter == 300:
        obstacle_pos.setSFVec3f(obs_en_router)
