"""Port of Webots' tests/api/controllers/supervisor_proto: the PROTO chain of a node (type names, isDerived,
parents) and the fields each PROTO of the chain declares (count, names and types), for a PROTO instance and for a
node defined inside it.

Webots' Python API of R2025a is used (Proto.getParent, getField, getFieldByIndex, getNumberOfFields, isDerived).
The C test's first checks pass NULL to each wb_supervisor_proto_* function; Python has no NULL proto to pass, so
they are not ported.
"""

from controller import Field, Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_boolean_not_equal,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_assert_pointer_null,
    ts_assert_string_equal,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32


def assert_hierarchy_correct(proto, expected_hierarchy, node_name):
    for i, expected in enumerate(expected_hierarchy):
        actual_name = proto.getTypeName() if proto is not None else None
        ts_assert_pointer_not_null(actual_name, '(%s) Hierarchy mismatch! Expected "%s", but got NULL', node_name,
                                   expected)
        ts_assert_string_equal(actual_name, expected, '(%s) Hierarchy mismatch! Expected "%s", but got "%s"', node_name,
                               expected, actual_name)
        if i + 1 < len(expected_hierarchy):
            ts_assert_boolean_equal(proto.isDerived(), '(%s) wb_supervisor_proto_is_derived() should return true for "%s"',
                                    node_name, actual_name)
        else:
            ts_assert_boolean_not_equal(proto.isDerived(),
                                        '(%s) wb_supervisor_proto_is_derived() should return false for "%s"', node_name,
                                        actual_name)
        proto = proto.getParent()
    ts_assert_pointer_null(proto, '(%s) Hierarchy mismatch! Expected NULL, but got "%s"', node_name,
                           proto.getTypeName() if proto is not None else "")


def assert_fields_correct(proto, expected_fields, node_name):
    for fields in expected_fields:
        ts_assert_pointer_not_null(proto, "(%s) Expected more fields, but proto is null. The test should've failed when "
                                   "checking the hierarchy. This likely means that the expected values are incorrectly "
                                   "configured.", node_name)
        number_of_fields = len(fields)
        proto_name = proto.getTypeName()
        actual_number_of_fields = proto.getNumberOfFields()
        ts_assert_int_equal(actual_number_of_fields, number_of_fields,
                            '(%s) Wrong number of fields in proto "%s". Expected %d, but got %d', node_name, proto_name,
                            number_of_fields, actual_number_of_fields)
        for j, (expected_name, expected_type) in enumerate(fields):
            field = proto.getFieldByIndex(j)
            ts_assert_pointer_not_null(field, '(%s) Field "%d" not found in proto "%s" despite the reported number of '
                                       'fields being correct', node_name, j, proto_name)
            actual_name = field.getName()
            ts_assert_string_equal(actual_name, expected_name, '(%s) Field mismatch in proto "%s"! Expected "%s", but got '
                                   '"%s"', node_name, proto_name, expected_name, actual_name)
            actual_type = field.getType()
            ts_assert_int_equal(actual_type, expected_type, '(%s) Field "%s" in proto "%s" has wrong type! Expected %d, '
                                'but got %d', node_name, expected_name, proto_name, expected_type, actual_type)
        proto = proto.getParent()


robot = Supervisor()
ts_setup(robot)

expected_hierarchy = ["SolidProtoHierarchy", "SolidProtoHierarchyInternal", "SolidProtoHierarchyBase"]
expected_fields = [
    [("translationStep", Field.SF_FLOAT), ("internalTranslationStep", Field.SF_FLOAT),
     ("internalField1", Field.SF_FLOAT), ("internalField2", Field.SF_FLOAT), ("ucField4", Field.SF_FLOAT)],
    [("translationStep", Field.SF_FLOAT), ("rotationStep", Field.SF_FLOAT), ("children", Field.MF_NODE),
     ("ucField1", Field.SF_FLOAT), ("ucField2", Field.SF_FLOAT), ("ucField3", Field.SF_FLOAT)],
    [("translationStep", Field.SF_FLOAT), ("rotationStep", Field.SF_FLOAT), ("children", Field.MF_NODE),
     ("ucField1", Field.SF_FLOAT)],
]

hierarchy = robot.getFromDef("HIERARCHY")
ts_assert_pointer_not_null(hierarchy, "Hierarchy node not found")
internal_node = hierarchy.getFromProtoDef("INTERNAL_NODE")
ts_assert_pointer_not_null(internal_node, "Internal node not found")

hierarchy_proto = hierarchy.getProto()
internal_proto = internal_node.getProto()

assert_hierarchy_correct(hierarchy_proto, expected_hierarchy, "HIERARCHY")
assert_fields_correct(hierarchy_proto, expected_fields, "HIERARCHY")
assert_hierarchy_correct(internal_proto, expected_hierarchy[1:], "INTERNAL_NODE")
assert_fields_correct(internal_proto, expected_fields[1:], "INTERNAL_NODE")

ts_send_success()
