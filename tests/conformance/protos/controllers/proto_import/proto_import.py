"""Port of Webots' tests/protos/controllers/proto_import: importing PROTO instances from strings works for a PROTO the
world declares (IMPORTABLE EXTERNPROTO), whether from Webots' library (Nao) or not (DeclaredProto), and does not for
one the world does not declare, a library one (Darwin-op) or an unknown one."""

from controller import Supervisor
from ts_assertion import ts_assert_pointer_not_null, ts_assert_pointer_null, ts_send_success, ts_setup

TIME_STEP = 64

robot = Supervisor()
ts_setup(robot)

root_node = robot.getRoot()
root_children_field = root_node.getField("children")

# import case: declared as EXTERNPROTO and is an official PROTO
root_children_field.importMFNodeFromString(-1, "DEF NAO Nao { }")
nao_node = robot.getFromDef("NAO")

# import case: declared as EXTERNPROTO but is not an official PROTO
root_children_field.importMFNodeFromString(-1, "DEF DECLARED_PROTO DeclaredProto { }")
custom_proto_node = robot.getFromDef("DECLARED_PROTO")

# import case: not declared as EXTERNPROTO but is an official PROTO
root_children_field.importMFNodeFromString(-1, "DEF DARWIN_OP Darwin-op { }")
darwin_node = robot.getFromDef("DARWIN_OP")

# import case: not declared as EXTERNPROTO and is not an official PROTO
root_children_field.importMFNodeFromString(-1, "DEF NONEXISTANT_PROTO UndeclaredProto { }")
non_existant_node = robot.getFromDef("UNDECLARED_PROTO")

robot.step(TIME_STEP)

ts_assert_pointer_not_null(nao_node, "Importing of 'Nao' robot should work but does not.")
ts_assert_pointer_not_null(custom_proto_node, "Importing of 'CustomProto' robot should work but does not.")
ts_assert_pointer_null(darwin_node, "Importing of 'Darwin-Op' robot should not be possible.")
ts_assert_pointer_null(non_existant_node, "Importing of 'NonExistantProto' robot should not be possible.")

ts_send_success()
