"""Port of Webots' tests/protos/controllers/template_indirect_field_reference: a template reads its parameters through
an object passed to a function, here two unconnectedField values whose sum (6) is the radarCrossSection of the Solid
the PROTO expands to, read as an internal field of the PROTO instance (wb_supervisor_node_get_proto_field, R2024a;
Python's Node.getProtoField).

Run by template_indirect_field_reference.wbt (JavaScript template) and its _lua variant (Lua template). The test name
comes from controllerArgs, as the C original's ts_setup(argv[1]); its spaces become underscores because the runner's
result lines are space-separated ("template_indirect_field_reference (lua)" ->
"template_indirect_field_reference_(lua)").
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])  # give the controller args
proto = robot.getFromDef("PROTO_TEMPLATE_INDIRECT_FIELD_REFERENCE")
radarCrossSection = proto.getProtoField("radarCrossSection")
ts_assert_double_in_delta(radarCrossSection.getSFFloat(), 6.0, 0.0001, "radarCrossSection should be 6.0")
ts_send_success()
