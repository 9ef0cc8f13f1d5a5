"""Port of Webots' tests/api/controllers/supervisor_proto_fields: the fields of a PROTO chain read through
Proto.getField and Node.getBaseNodeField are read-only views of the scene-tree field getActualField names; writing
them changes nothing, and writing the actual fields shows the new value at every level.

Webots' Python API of R2025a is used (Proto.getParent and Proto.getField).
"""

from controller import Field, Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_equal,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

NUMBER_OF_MAIN_FIELDS = 7
NUMBER_OF_INTERNAL_FIELDS = 6
NUMBER_OF_HIERARCHY_LEVELS = 4


def retrieve_fields(main_field_names, internal_field_names, hierarchy):
    """(actual_main_fields, actual_internal_fields, main_fields, internal_fields), as the C test fills them."""
    actual_main_fields = [None] * NUMBER_OF_MAIN_FIELDS
    actual_internal_fields = [None] * NUMBER_OF_INTERNAL_FIELDS
    main_fields = [[None] * NUMBER_OF_HIERARCHY_LEVELS for _ in range(NUMBER_OF_MAIN_FIELDS)]
    internal_fields = [[None] * NUMBER_OF_HIERARCHY_LEVELS for _ in range(NUMBER_OF_INTERNAL_FIELDS)]

    for i in range(NUMBER_OF_MAIN_FIELDS):
        name = main_field_names[i][0]
        if not name:
            continue
        field = hierarchy.getField(name)
        ts_assert_pointer_not_null(field, 'Field "%s" not found', name)
        actual_main_fields[i] = field.getActualField()

    for i in range(NUMBER_OF_INTERNAL_FIELDS):
        name = internal_field_names[i][0]
        if not name:
            continue
        field = hierarchy.getField(name)
        ts_assert_pointer_not_null(field, 'Field "%s" not found', name)
        actual_internal_fields[i] = field.getActualField()

    hierarchy_proto = hierarchy.getProto()
    ts_assert_pointer_not_null(hierarchy_proto, "Hierarchy proto not found")

    proto_type = hierarchy_proto.getTypeName()
    for i in range(NUMBER_OF_INTERNAL_FIELDS):
        field_name = internal_field_names[i][0]
        if field_name:
            field = hierarchy_proto.getField(field_name)
            ts_assert_pointer_not_null(field, 'Field "%s" not found in proto of type "%s"', field_name, proto_type)
            internal_fields[i][0] = field

    for i in range(NUMBER_OF_HIERARCHY_LEVELS - 1):
        ts_assert_pointer_not_null(hierarchy_proto, "Hierarchy level %d does not exist. Try running the supervisor_proto "
                                   "test for more information.", i)
        proto_type = hierarchy_proto.getTypeName()
        for j in range(NUMBER_OF_MAIN_FIELDS):
            name = main_field_names[j][i]
            if name:
                field = hierarchy_proto.getField(name)
                ts_assert_pointer_not_null(field, 'Field "%s" not found in proto of type "%s"', name, proto_type)
                main_fields[j][i] = field
        hierarchy_proto = hierarchy_proto.getParent()

    for i in range(NUMBER_OF_MAIN_FIELDS):
        name = main_field_names[i][NUMBER_OF_HIERARCHY_LEVELS - 1]
        if name:
            field = hierarchy.getBaseNodeField(name)
            ts_assert_pointer_not_null(field, 'Field "%s" not found in base hierarchy node', name)
            main_fields[i][NUMBER_OF_HIERARCHY_LEVELS - 1] = field

    internal_node = hierarchy.getFromProtoDef("INTERNAL_NODE")
    ts_assert_pointer_not_null(internal_node, "Internal node not found")
    internal_proto = internal_node.getProto()
    ts_assert_pointer_not_null(internal_proto, "Internal node proto not found")

    for i in range(1, NUMBER_OF_HIERARCHY_LEVELS - 1):
        ts_assert_pointer_not_null(internal_proto, "Hierarchy level %d does not exist. Try running the supervisor_proto "
                                   "test for more information.", i)
        proto_type = internal_proto.getTypeName()
        for j in range(NUMBER_OF_INTERNAL_FIELDS):
            name = internal_field_names[j][i]
            if name:
                field = internal_proto.getField(name)
                ts_assert_pointer_not_null(field, 'Field "%s" not found in proto of type "%s"', name, proto_type)
                internal_fields[j][i] = field
        internal_proto = internal_proto.getParent()

    for i in range(NUMBER_OF_INTERNAL_FIELDS):
        name = internal_field_names[i][NUMBER_OF_HIERARCHY_LEVELS - 1]
        if name:
            field = internal_node.getBaseNodeField(name)
            ts_assert_pointer_not_null(field, 'Field "%s" not found in base internal node', name)
            internal_fields[i][NUMBER_OF_HIERARCHY_LEVELS - 1] = field

    return actual_main_fields, actual_internal_fields, main_fields, internal_fields


def check_field(field, actual_field, expected_value, name, check_name):
    ts_assert_pointer_not_null(field, '(%s) Field "%s" not found', check_name, name)
    field_type = field.getType()
    ts_assert_int_equal(field_type, Field.SF_FLOAT, '(%s) Field "%s" is not an SFFloat. Got type: %d', check_name, name,
                        field_type)
    ts_assert_boolean_equal(field.getActualField() == actual_field, '(%s) Field "%s" actual field mismatch', check_name,
                            name)
    actual_value = field.getSFFloat()
    ts_assert_double_equal(actual_value, expected_value, '(%s) Field "%s" value mismatch! Expected %f, but got %f',
                           check_name, name, expected_value, actual_value)


robot = Supervisor()
ts_setup(robot)

main_field_names = [
    ["translationStep", "translationStep", "translationStep", "translationStep"],
    ["internalField1", "ucField2", None, None],
    ["ucField4", None, None, None],
    [None, "rotationStep", "rotationStep", "rotationStep"],
    [None, "ucField1", "ucField1", None],
    [None, "ucField3", None, None],
    [None, None, None, "radarCrossSection"],
]
internal_field_names = [
    ["internalTranslationStep", "translationStep", "translationStep", "translationStep"],
    ["internalField2", "ucField2", None, None],
    [None, "rotationStep", "rotationStep", "rotationStep"],
    [None, "ucField1", "ucField1", None],
    [None, "ucField3", None, None],
    [None, None, None, "radarCrossSection"],
]

hierarchy = robot.getFromDef("HIERARCHY")
ts_assert_pointer_not_null(hierarchy, "Hierarchy node not found")

actual_main, actual_internal, main_fields, internal_fields = retrieve_fields(main_field_names, internal_field_names,
                                                                             hierarchy)

for i in range(NUMBER_OF_MAIN_FIELDS):
    if actual_main[i]:
        check_field(actual_main[i], actual_main[i], 0.01, main_field_names[i][0], "Initial value [main field]")

for i in range(NUMBER_OF_INTERNAL_FIELDS):
    if actual_internal[i]:
        check_field(actual_internal[i], actual_internal[i], 0.01, internal_field_names[i][0],
                    "Initial value [internal field]")

for i in range(NUMBER_OF_MAIN_FIELDS):
    for j in range(NUMBER_OF_HIERARCHY_LEVELS):
        if main_fields[i][j]:
            check_field(main_fields[i][j], actual_main[i], 0.01, main_field_names[i][j], "Initial value [main field]")
            main_fields[i][j].setSFFloat(1.01)

for i in range(NUMBER_OF_INTERNAL_FIELDS):
    for j in range(NUMBER_OF_HIERARCHY_LEVELS):
        if internal_fields[i][j]:
            check_field(internal_fields[i][j], actual_internal[i], 0.01, internal_field_names[i][j],
                        "Initial value [internal field]")
            internal_fields[i][j].setSFFloat(1.01)

robot.step(TIME_STEP)

actual_main, actual_internal, main_fields, internal_fields = retrieve_fields(main_field_names, internal_field_names,
                                                                             hierarchy)

for i in range(NUMBER_OF_MAIN_FIELDS):
    if actual_main[i]:
        check_field(actual_main[i], actual_main[i], 0.01, main_field_names[i][0], "Update read-only field [main field]")
    for j in range(NUMBER_OF_HIERARCHY_LEVELS):
        if main_fields[i][j]:
            check_field(main_fields[i][j], actual_main[i], 0.01, main_field_names[i][j],
                        "Update read-only field [main field]")

for i in range(NUMBER_OF_INTERNAL_FIELDS):
    if actual_internal[i]:
        check_field(actual_internal[i], actual_internal[i], 0.01, internal_field_names[i][0],
                    "Update read-only field [internal field]")
    for j in range(NUMBER_OF_HIERARCHY_LEVELS):
        if internal_fields[i][j]:
            check_field(internal_fields[i][j], actual_internal[i], 0.01, internal_field_names[i][j],
                        "Update read-only field [internal field]")

for i in range(NUMBER_OF_MAIN_FIELDS):
    if actual_main[i]:
        actual_main[i].setSFFloat(float(i))

for i in range(NUMBER_OF_INTERNAL_FIELDS):
    if actual_internal[i]:
        actual_internal[i].setSFFloat(float(i))

robot.step(TIME_STEP)

actual_main, actual_internal, main_fields, internal_fields = retrieve_fields(main_field_names, internal_field_names,
                                                                             hierarchy)

for i in range(NUMBER_OF_MAIN_FIELDS):
    if actual_main[i]:
        check_field(actual_main[i], actual_main[i], i, main_field_names[i][0], "Update field [main field]")
    for j in range(NUMBER_OF_HIERARCHY_LEVELS):
        if main_fields[i][j]:
            check_field(main_fields[i][j], actual_main[i], i if actual_main[i] else 0.01, main_field_names[i][j],
                        "Update field [main field]")

for i in range(NUMBER_OF_INTERNAL_FIELDS):
    if actual_internal[i]:
        check_field(actual_internal[i], actual_internal[i], i, internal_field_names[i][0],
                    "Update field [internal field]")
    for j in range(NUMBER_OF_HIERARCHY_LEVELS):
        if internal_fields[i][j]:
            check_field(internal_fields[i][j], actual_internal[i], i if actual_internal[i] else 0.01,
                        internal_field_names[i][j], "Update field [internal field]")

ts_send_success()
