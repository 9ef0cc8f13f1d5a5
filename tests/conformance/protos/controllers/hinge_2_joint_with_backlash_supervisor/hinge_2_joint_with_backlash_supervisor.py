"""Port of Webots' tests/protos/controllers/hinge_2_joint_with_backlash_supervisor: four Hinge2JointWithBacklash
(Webots' library PROTO; backlash on both axes, on axis, on axis2, on neither) and a reference Hinge2Joint are driven
on axis2 only, then (after a simulation reset and a restart of the robot's controller) on axis only: the joints
without backlash on the driven axis follow the reference, those with backlash lag it, and none overshoots it.

The velocities are sent as two C floats (struct "ff"). `TIME_STEP / 1000` is C integer division (0).
"""

import math
import struct

from controller import Supervisor
from ts_assertion import (
    ts_assert_double_in_delta,
    ts_assert_double_is_bigger,
    ts_assert_vec3_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 16
TEST_DURATION = 10.0
VELOCITY = 0.2

BACKLASH_ON_BOTH, BACKLASH_ON_AXIS, BACKLASH_ON_AXIS2, BACKLASH_ON_NEITHER, REFERENCE_HINGE2JOINT = range(5)
X, Y, Z = range(3)

supervisor = Supervisor()
ts_setup(supervisor)

robot = supervisor.getFromDef("ROBOT")
emitter = supervisor.getDevice("emitter")

end_point_node = [None] * 5
end_point_node[BACKLASH_ON_BOTH] = supervisor.getFromDef("END_POINT_CASE_BACKLASH_ON_BOTH")
end_point_node[BACKLASH_ON_AXIS] = supervisor.getFromDef("END_POINT_CASE_BACKLASH_ON_AXIS")
end_point_node[BACKLASH_ON_AXIS2] = supervisor.getFromDef("END_POINT_CASE_BACKLASH_ON_AXIS2")
end_point_node[BACKLASH_ON_NEITHER] = supervisor.getFromDef("END_POINT_CASE_BACKLASH_ON_NEITHER")
end_point_node[REFERENCE_HINGE2JOINT] = supervisor.getFromDef("END_POINT_CASE_REFERENCE_HINGE2JOINT")
end_point_position = [None] * 5

reference_min_z = math.inf
reference_max_z = -math.inf

# Test: in this test only axis2 is actuated, the joints with no backlash in this direction should behave like the
# reference.
outbuffer = [0.0, VELOCITY]
while supervisor.step(TIME_STEP) != -1 and supervisor.getTime() < TEST_DURATION:
    # send command
    emitter.send(struct.pack("ff", *outbuffer))
    if supervisor.getTime() <= TIME_STEP // 1000:
        continue  # give controllers time to receive commands and start
    # monitoring
    for case in range(5):
        end_point_position[case] = end_point_node[case].getPosition()

    # Test: verify that no endpoint changes in the X direction
    tolerance = 1e-10
    ts_assert_double_in_delta(end_point_position[BACKLASH_ON_BOTH][X], 0, tolerance,
                              "In test case 'BACKLASH_ON_BOTH' the endpoint moved in X when shouldn't.")
    ts_assert_double_in_delta(end_point_position[BACKLASH_ON_AXIS][X], 0, tolerance,
                              "In test case 'BACKLASH_ON_AXIS' the endpoint moved in X when shouldn't.")
    ts_assert_double_in_delta(end_point_position[BACKLASH_ON_AXIS2][X], 0, tolerance,
                              "In test case 'BACKLASH_ON_AXIS2 the endpoint moved in X when shouldn't.")
    ts_assert_double_in_delta(end_point_position[BACKLASH_ON_NEITHER][X], 0, tolerance,
                              "In test case 'BACKLASH_ON_NEITHER' the endpoint moved in X when shouldn't.")
    ts_assert_double_in_delta(end_point_position[REFERENCE_HINGE2JOINT][X], 0, tolerance,
                              "In test case 'REFERENCE_HINGE2JOINT' the endpoint moved in X when shouldn't.")

    # keep track of reference position (minimum and maximum value of Z, adjusted by offset)
    if end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0 > reference_max_z:
        reference_max_z = end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0
    if end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0 < reference_min_z:
        reference_min_z = end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0

    # Test: no endpoint should swing beyond neither the current nor the maximal value reached by the reference.
    # check against the maxima
    tolerance = 1e-8
    ts_assert_double_is_bigger(reference_max_z + tolerance, end_point_position[BACKLASH_ON_BOTH][Z],
                               "In test case 'BACKLASH_ON_BOTH' the endpoint breached the reference's maximal Z position.")
    ts_assert_double_is_bigger(reference_max_z + tolerance, end_point_position[BACKLASH_ON_AXIS][Z] + 0.25,
                               "In test case 'BACKLASH_ON_AXIS' the endpoint breached reference's maximal Z position.")
    ts_assert_double_is_bigger(reference_max_z + tolerance, end_point_position[BACKLASH_ON_AXIS2][Z] + 0.50,
                               "In test case 'BACKLASH_ON_AXIS2' the endpoint breached reference's maximal Z position.")
    ts_assert_double_is_bigger(reference_max_z + tolerance, end_point_position[BACKLASH_ON_NEITHER][Z] + 0.75,
                               "In test case 'BACKLASH_ON_NEITHER' the endpoint breached reference's maximal Z position.")

    # check against the minima
    tolerance = 1e-10
    ts_assert_double_is_bigger(end_point_position[BACKLASH_ON_BOTH][Z], reference_min_z - tolerance,
                               "In test case 'BACKLASH_ON_BOTH' the endpoint breached reference's minimal Z position.")
    ts_assert_double_is_bigger(end_point_position[BACKLASH_ON_AXIS][Z] + 0.25, reference_min_z - tolerance,
                               "In test case 'BACKLASH_ON_AXIS' the endpoint breached reference's minimal Z position.")
    ts_assert_double_is_bigger(end_point_position[BACKLASH_ON_AXIS2][Z] + 0.50, reference_min_z - tolerance,
                               "In test case 'BACKLASH_ON_AXIS2' the endpoint breached reference's minimal Z position.")
    ts_assert_double_is_bigger(end_point_position[BACKLASH_ON_NEITHER][Z] + 0.75, reference_min_z - tolerance,
                               "In test case 'BACKLASH_ON_NEITHER' the endpoint breached reference's minimal Z position.")

    # TEST: assert if behavior is consistent (those with backlash behave all the same, those without as well)
    # (BACKLASH_ON_BOTH, BACKLASH_ON_AXIS2) should behave in the same manner
    tolerance = 1e-7
    ts_assert_vec3_in_delta(end_point_position[BACKLASH_ON_BOTH][X], end_point_position[BACKLASH_ON_BOTH][Y],
                            end_point_position[BACKLASH_ON_BOTH][Z], end_point_position[BACKLASH_ON_AXIS2][X],
                            end_point_position[BACKLASH_ON_AXIS2][Y], end_point_position[BACKLASH_ON_AXIS2][Z] + 0.50,
                            tolerance, "'BACKLASH_ON_BOTH' and 'BACKLASH_ON_AXIS2' are not behaving in the same manner.")

    # (BACKLASH_ON_AXIS, BACKLASH_ON_NEITHER, REFERENCE_HINGE2JOINT) should behave in the same manner
    ts_assert_vec3_in_delta(end_point_position[BACKLASH_ON_AXIS][X], end_point_position[BACKLASH_ON_AXIS][Y],
                            end_point_position[BACKLASH_ON_AXIS][Z] + 0.25, end_point_position[REFERENCE_HINGE2JOINT][X],
                            end_point_position[REFERENCE_HINGE2JOINT][Y], end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0,
                            tolerance, "'BACKLASH_ON_AXIS' and 'REFERENCE_HINGE2JOINT' not behaving in the same manner.")

    ts_assert_vec3_in_delta(end_point_position[BACKLASH_ON_NEITHER][X], end_point_position[BACKLASH_ON_NEITHER][Y],
                            end_point_position[BACKLASH_ON_NEITHER][Z] + 0.75, end_point_position[REFERENCE_HINGE2JOINT][X],
                            end_point_position[REFERENCE_HINGE2JOINT][Y], end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0,
                            tolerance, "'BACKLASH_ON_NEITHER' and 'REFERENCE_HINGE2JOINT' not behaving in the same manner.")

    # the first group should behave differently from the second
    minimal_difference = 1e-3  # we don't want them to be similar at all
    if supervisor.getTime() > 0.5 and supervisor.getTime() < 2.5:  # sufficient to test that they start differently
        ts_assert_double_is_bigger(
            math.fabs(end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0) - math.fabs(end_point_position[BACKLASH_ON_BOTH][Z]),
            minimal_difference, "'BACKLASH_ON_BOTH' and 'REFERENCE_HINGE2JOINT' behave similarly but shouldn't.")

supervisor.simulationReset()
robot.restartController()

supervisor.step(TIME_STEP)

reference_min_x = math.inf
reference_max_x = -math.inf

# Test: in this test only axis is actuated, the joints with no backlash in this direction should behave like the reference.
outbuffer[0] = VELOCITY
outbuffer[1] = 0.0
while supervisor.step(TIME_STEP) != -1 and supervisor.getTime() < TEST_DURATION:
    # send command
    emitter.send(struct.pack("ff", *outbuffer))
    if supervisor.getTime() <= TIME_STEP // 1000:
        continue  # give controllers time to receive commands and start
    # monitoring
    for case in range(5):
        end_point_position[case] = end_point_node[case].getPosition()

    # Test: verify that no endpoint changes in the Z direction
    ts_assert_double_in_delta(end_point_position[BACKLASH_ON_BOTH][Z], 0, 1e-10,
                              "In test case 'BACKLASH_ON_BOTH' the endpoint moved in Z when shouldn't.")
    ts_assert_double_in_delta(end_point_position[BACKLASH_ON_AXIS][Z], -0.25, 1e-10,
                              "In test case 'BACKLASH_ON_AXIS' the endpoint moved in Z when shouldn't.")
    ts_assert_double_in_delta(end_point_position[BACKLASH_ON_AXIS2][Z], -0.50, 1e-10,
                              "In test case 'BACKLASH_ON_AXIS2 the endpoint moved in Z when shouldn't.")
    ts_assert_double_in_delta(end_point_position[BACKLASH_ON_NEITHER][Z], -0.75, 1e-10,
                              "In test case 'BACKLASH_ON_NEITHER' the endpoint moved in Z when shouldn't.")
    ts_assert_double_in_delta(end_point_position[REFERENCE_HINGE2JOINT][Z], -1.0, 1e-10,
                              "In test case 'REFERENCE_HINGE2JOINT' the endpoint moved in Z when shouldn't.")

    # keep track of reference position (minimum and maximum value of X)
    if end_point_position[REFERENCE_HINGE2JOINT][X] > reference_max_x:
        reference_max_x = end_point_position[REFERENCE_HINGE2JOINT][X]
    if end_point_position[REFERENCE_HINGE2JOINT][X] < reference_min_x:
        reference_min_x = end_point_position[REFERENCE_HINGE2JOINT][X]

    # TEST: no endpoint should swing beyond neither the current nor the maximal value reached by the reference
    # check against the maxima
    tolerance = 1e-8
    ts_assert_double_is_bigger(reference_max_x + tolerance, end_point_position[BACKLASH_ON_BOTH][X],
                               "In test case 'BACKLASH_ON_BOTH' the endpoint breached the reference's maximal X position.")
    ts_assert_double_is_bigger(reference_max_x + tolerance, end_point_position[BACKLASH_ON_AXIS][X],
                               "In test case 'BACKLASH_ON_AXIS' the endpoint breached reference's maximal X position.")
    ts_assert_double_is_bigger(reference_max_x + tolerance, end_point_position[BACKLASH_ON_AXIS2][X],
                               "In test case 'BACKLASH_ON_AXIS2' the endpoint breached reference's maximal X position.")
    ts_assert_double_is_bigger(reference_max_x + tolerance, end_point_position[BACKLASH_ON_NEITHER][X],
                               "In test case 'BACKLASH_ON_NEITHER' the endpoint breached reference's maximal X position.")

    # check against the minima
    tolerance = 1e-10
    ts_assert_double_is_bigger(end_point_position[BACKLASH_ON_BOTH][X], reference_min_x - tolerance,
                               "In test case 'BACKLASH_ON_BOTH' the endpoint breached reference's minimal X position.")
    ts_assert_double_is_bigger(end_point_position[BACKLASH_ON_AXIS][X], reference_min_x - tolerance,
                               "In test case 'BACKLASH_ON_AXIS' the endpoint reference's minimal X position.")
    ts_assert_double_is_bigger(end_point_position[BACKLASH_ON_AXIS2][X], reference_min_x - tolerance,
                               "In test case 'BACKLASH_ON_AXIS2' the endpoint reference's minimal X position.")
    ts_assert_double_is_bigger(end_point_position[BACKLASH_ON_NEITHER][X], reference_min_x - tolerance,
                               "In test case 'BACKLASH_ON_NEITHER' the endpoint reference's minimal X position.")

    # TEST: assert if behavior is consistent (those with backlash behave all the same, those without as well)
    # (BACKLASH_ON_BOTH, BACKLASH_ON_AXIS) should behave in the same manner
    tolerance = 1e-8
    ts_assert_vec3_in_delta(end_point_position[BACKLASH_ON_BOTH][X], end_point_position[BACKLASH_ON_BOTH][Y],
                            end_point_position[BACKLASH_ON_BOTH][Z], end_point_position[BACKLASH_ON_AXIS][X],
                            end_point_position[BACKLASH_ON_AXIS][Y], end_point_position[BACKLASH_ON_AXIS][Z] + 0.25, tolerance,
                            "'BACKLASH_ON_BOTH' and 'BACKLASH_ON_AXIS' are not behaving in the same manner.")

    # (BACKLASH_ON_AXIS2, BACKLASH_ON_NEITHER, REFERENCE_HINGE2JOINT) should behave in the same manner
    ts_assert_vec3_in_delta(end_point_position[BACKLASH_ON_AXIS2][X], end_point_position[BACKLASH_ON_AXIS2][Y],
                            end_point_position[BACKLASH_ON_AXIS2][Z] + 0.50, end_point_position[REFERENCE_HINGE2JOINT][X],
                            end_point_position[REFERENCE_HINGE2JOINT][Y], end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0,
                            tolerance, "'BACKLASH_ON_AXIS2' and 'REFERENCE_HINGE2JOINT' not behaving in the same manner.")

    ts_assert_vec3_in_delta(end_point_position[BACKLASH_ON_NEITHER][X], end_point_position[BACKLASH_ON_NEITHER][Y],
                            end_point_position[BACKLASH_ON_NEITHER][Z] + 0.75, end_point_position[REFERENCE_HINGE2JOINT][X],
                            end_point_position[REFERENCE_HINGE2JOINT][Y], end_point_position[REFERENCE_HINGE2JOINT][Z] + 1.0,
                            tolerance, "'BACKLASH_ON_NEITHER' and 'REFERENCE_HINGE2JOINT' not behaving in the same manner.")

    # the first group should behave differently from the second
    minimal_difference = 1e-3  # we don't want them to be similar at all
    if supervisor.getTime() > 0.5 and supervisor.getTime() < 2.5:  # sufficient to test that they start differently
        ts_assert_double_is_bigger(
            math.fabs(end_point_position[REFERENCE_HINGE2JOINT][X]) - math.fabs(end_point_position[BACKLASH_ON_BOTH][X]),
            minimal_difference, "'BACKLASH_ON_BOTH' and 'REFERENCE_HINGE2JOINT' behave similarly but shouldn't.")

ts_send_success()
