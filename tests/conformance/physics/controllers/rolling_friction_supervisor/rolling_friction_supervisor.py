"""Port of Webots' tests/physics/controllers/rolling_friction_supervisor: ContactProperties rollingFriction."""

from controller import Supervisor
from ts_assertion import (
    ts_assert_double_in_delta,
    ts_assert_double_is_bigger,
    ts_assert_doubles_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)
lateral_velocity = [0, 0, 0, -25, 0, 0]
spinning_velocity = [0, 0, 0, 0, 0, 25]
balls = [robot.getFromDef("BALL_%d" % (i + 1)) for i in range(9)]

# An initial push for the balls testing rho2 and rhoN.
for i in range(3, 9):
    balls[i].setVelocity(spinning_velocity if i < 6 else lateral_velocity)
initial_position = [list(ball.getPosition()) for ball in balls]

robot.step(100 * TIME_STEP)
v = [list(ball.getVelocity()) for ball in balls]

# rho alone: more rolling friction, slower.
ts_assert_double_is_bigger(v[0][0], v[1][0], "BALL_1 should have higher linear speed than BALL_2.")
ts_assert_double_is_bigger(v[1][0], v[2][0], "BALL_2 should have higher linear speed than BALL_3.")
ts_assert_double_is_bigger(v[0][4], v[1][4], "BALL_1 should have higher angular speed than BALL_2.")
ts_assert_double_is_bigger(v[1][4], v[2][4], "BALL_2 should have higher angular speed than BALL_3.")
for i in range(3):
    ts_assert_double_in_delta(v[i][3], 0.0, 1e-6, "%s spinning in the wrong direction.", "BALL_%d" % (i + 1))
    ts_assert_double_in_delta(v[i][5], 0.0, 1e-6, "%s spinning in the wrong direction.", "BALL_%d" % (i + 1))

# rhoN alone: the spinning balls slow down in order, and only spin about z.
ts_assert_double_is_bigger(v[3][5], v[4][5], "BALL_4 should have higher angular speed than BALL_5.")
ts_assert_double_is_bigger(v[4][5], v[5][5], "BALL_5 should have higher angular speed than BALL_6.")
for i in range(3, 6):
    name = "BALL_%d" % (i + 1)
    ts_assert_doubles_in_delta(3, v[i][:3], [0.0, 0.0, 0.0], 1e-6, "%s should not have linear speed.", name)
    ts_assert_doubles_in_delta(2, v[i][3:5], [0.0, 0.0], 1e-6, "%s should not be spinning around x or y axis.", name)

# rho2: more friction, less sideways motion.
delta_y = [abs(initial_position[i][1] - balls[i].getPosition()[1]) for i in range(9)]
ts_assert_double_is_bigger(delta_y[6], delta_y[7], "BALL_7 should have bigger lateral displacement than BALL_8.")
ts_assert_double_is_bigger(delta_y[7], delta_y[8], "BALL_8 should have bigger lateral displacement than BALL_9.")

robot.step(100 * TIME_STEP)

# Webots' recorded poses and velocities after 200 steps.
expected_positions = [
    [-5.822856, -3.0, 0.498430], [-14.564553, 0.0, 0.498392], [-25.145860, 3.0, 1.942235],
    [-16.000000, -8.0, 1.498430], [-14.0, -8.0, 1.498430], [-12.0, -8.0, 1.498430],
    [-5.822856, -27.511330, 0.498430], [1.171054, -19.324655, 0.498430], [1.171054, -13.936790, 0.498430]]
expected_velocities = [
    [5.957204, 0.0, 0.0, 0.0, 11.951927, 0.0],
    [4.164077, 0.0, 0.000304, 0.0, 8.355176, 0.0],
    [1.817242, 0.0, -0.368373, 0.0, 3.719816, 0.0],
    [0.0, 0.0, 0.0, 0.0, 0.0, 25.0],
    [0.0, 0.0, 0.0, 0.0, 0.0, 6.164800],
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [5.957204, 3.686891, 0.0, -7.397003, 11.951927, -3.446233],
    [7.029157, 0.0, 0.0, 0.0, 0.0, -4.455340],
    [7.029157, 0.0, 0.0, 0.0, 0.0, -4.867729]]
for i, ball in enumerate(balls):
    name = "BALL_%d" % (i + 1)
    ts_assert_doubles_in_delta(3, ball.getPosition(), expected_positions[i], 1e-6,
                               "Position of %s is different from expected one.", name)
    ts_assert_doubles_in_delta(6, ball.getVelocity(), expected_velocities[i], 1e-6,
                               "Velocities of %s are different from expected one.", name)

ts_send_success()
