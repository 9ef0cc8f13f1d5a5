"""Port of Webots' tests/api/controllers/supervisor_field: the Field API of a supervisor: SF and MF getters and
setters of every type (PROTO parameters, internal PROTO fields read-only, wrong types and indices rejected), SF
tracking, a delayed set, removing a tracked node, a field reference made invalid by a PROTO regeneration, fields by
index, and the robot's 'supervisor' field switched off.

Where the C test expects NULL from an MF getter (index out of range, wrong field type), Webots' Python package raises
ValueError ("NULL pointer access"); the port counts that as NULL. C-only checks are not ported: calls with a NULL
field, and wb_supervisor_field_get_sf_float on an SFInt32 field (Python's getSFFloat returns the field's value
whatever its type), and wb_supervisor_field_set_mf_color on the url MFString field with the NULL array that the
previous getter returned.
"""

from controller import Node, Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_equal,
    ts_assert_doubles_equal,
    ts_assert_doubles_in_delta,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_assert_pointer_null,
    ts_assert_string_equal,
    ts_assert_vec3_equal,
    ts_assert_vec3_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32


def mf_or_null(getter, index):
    """An MF vector item, or None where the C function returns NULL (Python raises ValueError)."""
    try:
        return getter(index)
    except ValueError:
        return None


robot = Supervisor()
ts_setup(robot)

root = robot.getRoot()
ts_assert_pointer_not_null(root, "Root node is not found")

background = robot.getFromDef("BACKGROUND")
ts_assert_pointer_not_null(background, 'Node "BACKGROUND" is not found')

proto = robot.getFromDef("E_PUCK")
ts_assert_pointer_not_null(proto, 'Proto node "E_PUCK" is not found')

box = robot.getFromDef("BOX")
ts_assert_pointer_not_null(box, 'Node "BOX" is not found')

texture = robot.getFromDef("BOX_IMAGE_TEXTURE")
ts_assert_pointer_not_null(texture, 'Node "BOX_IMAGE_TEXTURE" is not found')

material = robot.getFromDef("BOX_MATERIAL")
ts_assert_pointer_not_null(texture, 'Node "BOX_MATERIAL" is not found')

shape = robot.getFromDef("BOX_SHAPE")
ts_assert_pointer_not_null(shape, 'Node "BOX_SHAPE" is not found')

plane = robot.getFromDef("PLANE")
ts_assert_pointer_not_null(plane, 'Node "PLANE" is not found')

mf_test = robot.getFromDef("MF_FIELDS")
ts_assert_pointer_not_null(mf_test, 'Node "MF_FIELDS" is not found')

# SFFloat PROTO parameter
field = proto.getField("camera_fieldOfView")
i = field.getType()
ts_assert_boolean_equal(i == field.SF_FLOAT, 'Proto "camera_fieldOfView" field should have type %d not %d', field.SF_FLOAT,
                        i)

char_array = field.getTypeName()
ts_assert_string_equal(char_array, "SFFloat", 'Proto "camera_fieldOfView" field should have type name "SFFloat" not "%s"',
                       char_array)

d = field.getSFFloat()
ts_assert_double_equal(d, 0.84, 'Proto "camera_fieldOfView" SFFloat field should have value 0.84 not %f', d)

field.setSFFloat(0.73)
d = field.getSFFloat()
ts_assert_double_equal(d, 0.73, 'Proto "camera_fieldOfView" SFFloat field should have value 0.73 not %f', d)

internal_field = box.getProtoField("scale")
ts_assert_pointer_null(internal_field, "wb_supervisor_node_get_proto_field should only work for PROTO nodes.")
internal_field = mf_test.getProtoField("mfBool")
ts_assert_pointer_null(internal_field, "wb_supervisor_node_get_proto_field should only work for internal PROTO fields.")

internal_sf_node_field = proto.getProtoField("physics")
ts_assert_pointer_not_null(internal_sf_node_field, "wb_supervisor_node_get_proto_field should return an internal field.")
internal_physics = internal_sf_node_field.getSFNode()
ts_assert_pointer_not_null(internal_physics, "wb_supervisor_field_get_sf_node should return an internal node.")
internal_field = internal_physics.getField("density")
ts_assert_pointer_not_null(internal_field, "wb_supervisor_node_get_proto_field should return an internal field.")
d = internal_field.getSFFloat()
ts_assert_double_equal(d, -1.0, "Returned value should be -1.0 and not %f", d)

internal_field = proto.getField("cpuConsumption")
ts_assert_pointer_null(internal_field, "wb_supervisor_node_get_field should not return internal fields.")
internal_field = proto.getProtoField("cpuConsumption")
ts_assert_pointer_not_null(internal_field, "wb_supervisor_node_get_proto_field should return an internal field.")
d = internal_field.getSFFloat()
ts_assert_double_equal(d, 1.11, "Returned value should be 1.11 and not %f", d)
internal_field.setSFFloat(1.5)

internal_appearance = proto.getFromProtoDef("EPUCK_TRANSPARENT_APPEARANCE")
ts_assert_pointer_not_null(internal_appearance, "wb_supervisor_node_get_from_proto_def should return the internal "
                           "EPUCK_TRANSPARENT_APPEARANCE node.")
internal_transparency_field = internal_appearance.getField("transparency")
ts_assert_pointer_not_null(internal_transparency_field, "wb_supervisor_node_get_field should return the field of the "
                           "internal EPUCK_TRANSPARENT_APPEARANCE node.")
internal_transparency_field.setSFFloat(0.0)
d = internal_transparency_field.getSFFloat()
ts_assert_double_equal(d, 0.4, "Returned value for invalid set of internal node should be 0.4 and not %f", d)

# SFFloat setter on an SFInt32 field
field = proto.getField("camera_height")
i = field.getType()
ts_assert_boolean_equal(i == field.SF_INT32, 'Proto "camera_height" field should have type %d not %d', field.SF_INT32, i)

field.setSFFloat(0.2)
i = field.getSFInt32()
ts_assert_int_equal(i, 39, "Returned value for SFInt32 field should be 39 not %d", i)

# MFColor
field = background.getField("skyColor")
i = field.getType()
ts_assert_boolean_equal(i == field.MF_COLOR, 'Background "skyColor" field should have type %d not %d', field.MF_COLOR, i)
char_array = field.getTypeName()
ts_assert_string_equal(char_array, "MFColor", 'Background "skyColor" field should have type name "MFColor" not "%s"',
                       char_array)

i = field.getCount()
ts_assert_int_equal(i, 3, 'Background "skyColor" mf_color field should have 3 items not %f', i)

double_array = field.getMFColor(0)
ts_assert_vec3_equal(double_array[0], double_array[1], double_array[2], 0.4, 0.7, 1,
                     'Item 0 of "skyColor" field of Background node should be [0.4, 0.7, 1] not [%f, %f, %f]',
                     double_array[0], double_array[1], double_array[2])
double_array = field.getMFColor(1)
ts_assert_vec3_equal(double_array[0], double_array[1], double_array[2], 0.5, 0.4, 0.74,
                     'Item 1 of "skyColor" field of Background node should be [0.5, 0.4 0.74] not [%f, %f, %f]',
                     double_array[0], double_array[1], double_array[2])
double_array = field.getMFColor(-1)
ts_assert_vec3_equal(double_array[0], double_array[1], double_array[2], 0.666667, 1.0, 0,
                     'Item 2 of "skyColor" field of Background node should be [0.666667, 1, 0] not [%f, %f, %f]',
                     double_array[0], double_array[1], double_array[2])
double_array = mf_or_null(field.getMFColor, 3)
ts_assert_pointer_null(double_array, "When requesting a MFColor field item with index out of bounds, the result should "
                       "be NULL")
double_array = mf_or_null(field.getMFColor, -4)
ts_assert_pointer_null(double_array, "When requesting a MFColor field item with index out of bounds, the result should "
                       "be NULL")

double_vec3 = [0.0, 0.0, 0.5]
field.setMFColor(0, double_vec3)
double_array = field.getMFColor(0)
ts_assert_vec3_equal(double_array[0], double_array[1], double_array[2], double_vec3[0], double_vec3[1], double_vec3[2],
                     'Item 0 of "skyColor" field of Background node should be [%f, %f, %f] not [%f, %f, %f] after '
                     'changing it', double_vec3[0], double_vec3[1], double_vec3[2], double_array[0], double_array[1],
                     double_array[2])

field.setMFColor(3, double_vec3)
field.setMFColor(-1, double_vec3)

# MF getter and setter of the wrong MF type
field = texture.getField("url")
i = field.getType()
ts_assert_boolean_equal(i == field.MF_STRING, 'Texture "url" field should have type %d not %d', field.MF_STRING, i)
double_array = mf_or_null(field.getMFColor, 0)
ts_assert_pointer_null(double_array, "Returned value for non MFColor fields should be NULL")

char_array = field.getMFString(0)[-21:]
ts_assert_string_equal(char_array, "textures/white256.png",
                       'Returned value for Texture url field should be "textures/white256.png", not "%s"', char_array)

# MF getter and setter on an SF field
field = material.getField("emissiveColor")
i = field.getType()
ts_assert_boolean_equal(i == field.SF_COLOR, 'Material "emissiveColor" field should have type %d not %d', field.SF_COLOR,
                        i)
double_array = mf_or_null(field.getMFColor, 0)
ts_assert_pointer_null(double_array, "Returned value for non MFColor fields should be NULL")
double_array = field.getSFColor()
ts_assert_vec3_equal(double_array[0], double_array[1], double_array[2], 1, 0.666, 0,
                     'Material "emissiveColor" field should be [1, 0.666, 0] not [%f, %f, %f]', double_array[0],
                     double_array[1], double_array[2])

field.setMFColor(0, double_array)
double_array = field.getSFColor()
ts_assert_vec3_equal(double_array[0], double_array[1], double_array[2], 1, 0.666, 0,
                     'Material "emissiveColor" field should be [1, 0.666, 0] not [%f, %f, %f]', double_array[0],
                     double_array[1], double_array[2])

# SFBool
field = shape.getField("castShadows")
cast_shadows_value = field.getSFBool()
ts_assert_boolean_equal(cast_shadows_value, "'wb_supervisor_field_get_sf_bool' failed")
field.setSFBool(False)
cast_shadows_value = field.getSFBool()
ts_assert_boolean_equal(not cast_shadows_value, "'wb_supervisor_field_set_sf_bool' failed")

# SFInt32
field = proto.getField("receiver_channel")
channel = field.getSFInt32()
ts_assert_int_equal(channel, 5, "'wb_supervisor_field_get_sf_int32' failed")
field.setSFInt32(12)
channel = field.getSFInt32()
ts_assert_int_equal(channel, 12, "'wb_supervisor_field_set_sf_int32' failed")

# SFString
field = box.getField("name")
sf_value1 = field.getSFString()
ts_assert_string_equal(sf_value1, "solid(1)", "'wb_supervisor_field_get_sf_string' failed: read \"%s\" instead of "
                       "\"solid\"", sf_value1)
field.setSFString("wrong")
field.setSFString("obstacle")
sf_value2 = field.getSFString()
ts_assert_string_equal(sf_value2, "obstacle", "'wb_supervisor_field_set_sf_string' failed: reading \"%s\" instead of "
                       "\"obstacle\"", sf_value2)

# SFVec2f
field = plane.getField("size")
vector2_expected = [1.0, 1.0]
ts_assert_doubles_equal(2, field.getSFVec2f(), vector2_expected, "'wb_supervisor_field_get_sf_vec2f' failed")
vector2_expected = [2.1, 5.0]
field.setSFVec2f(vector2_expected)
ts_assert_doubles_equal(2, field.getSFVec2f(), vector2_expected, "'wb_supervisor_field_set_sf_vec2f' failed")

# SFVec3f
field = box.getField("translation")
vector3_expected = [-0.2, 0.2, -0.2]
ts_assert_doubles_equal(3, field.getSFVec3f(), vector3_expected, "'wb_supervisor_field_get_sf_vec3f' failed")
vector3_expected = [0.123, 0.0, 0.7777]
field.setSFVec3f(vector3_expected)
ts_assert_doubles_equal(3, field.getSFVec3f(), vector3_expected, "'wb_supervisor_field_set_sf_vec3f' failed")

# SFRotation
field = box.getField("rotation")
rotation_expected = [0.70710339, 0.5000024, -0.5000024, 0.5708]
ts_assert_doubles_in_delta(4, field.getSFRotation(), rotation_expected, 1e-8,
                           "'wb_supervisor_field_get_sf_rotation' failed")
rotation_expected = [0.0, 1.0, 0.2585, 0.5708]
field.setSFRotation(rotation_expected)
ts_assert_doubles_equal(4, field.getSFRotation(), rotation_expected, "'wb_supervisor_field_set_sf_rotation' failed")

# SFNode
field = shape.getField("geometry")
box_geom = field.getSFNode()
ts_assert_boolean_equal(box_geom == robot.getFromDef("BOX_GEOM"), "'wb_supervisor_field_get_sf_node' failed")
field = box.getField("physics")
box_physics = field.getSFNode()
ts_assert_pointer_null(box_physics, "'wb_supervisor_field_get_sf_node' should return NULL for empty SFNode")

# MFBool
field = mf_test.getField("mfBool")
mf_bool = field.getMFBool(0)
ts_assert_boolean_equal(not mf_bool, "'wb_supervisor_field_get_mf_bool' failed")
field.setMFBool(0, True)
mf_bool = field.getMFBool(0)
ts_assert_boolean_equal(mf_bool, "'wb_supervisor_field_set_mf_bool' failed")

# MFInt32
field = mf_test.getField("mfInt")
mf_int = field.getMFInt32(1)
ts_assert_int_equal(mf_int, 0, "'wb_supervisor_field_get_mf_int32' failed")
field.setMFInt32(1, 11)
mf_int = field.getMFInt32(1)
ts_assert_int_equal(mf_int, 11, "'wb_supervisor_field_set_mf_int32' failed")

# MFString
field = mf_test.getField("mfString")
ts_assert_string_equal(field.getMFString(3), "test string", "'wb_supervisor_field_get_mf_string' failed")
field.setMFString(3, "ô")
ts_assert_string_equal(field.getMFString(3), "ô", "'wb_supervisor_field_get_mf_string' failed")

# MFVec2f
field = mf_test.getField("mfVec2")
mf_vector2_expected = [1.0, 1.0]
ts_assert_doubles_equal(2, field.getMFVec2f(1), mf_vector2_expected, "'wb_supervisor_field_get_mf_vec2f' failed")
mf_vector2_expected = [2.1, 5.0]
field.setMFVec2f(1, mf_vector2_expected)
ts_assert_doubles_equal(2, field.getMFVec2f(1), mf_vector2_expected, "'wb_supervisor_field_set_mf_vec2f' failed")

# MFVec3f
field = mf_test.getField("mfVec3")
mf_vector3_expected = [-0.2, 0.2, -0.2]
ts_assert_doubles_equal(3, field.getMFVec3f(-2), mf_vector3_expected, "'wb_supervisor_field_get_mf_vec3f' failed")
mf_vector3_expected = [0.123, 0.0, 0.7777]
field.setMFVec3f(-2, mf_vector3_expected)
ts_assert_doubles_equal(3, field.getMFVec3f(-2), mf_vector3_expected, "'wb_supervisor_field_get_mf_vec3f' failed")

# MFRotation
field = mf_test.getField("mfRotation")
mf_rotation_expected = [0.70717411, 0.49995239, -0.49995239, 0.5708]
ts_assert_doubles_equal(4, field.getMFRotation(0), mf_rotation_expected, "'wb_supervisor_field_get_mf_rotation' failed")
mf_rotation_expected = [0.0, 1.0, 0.2585, 0.5708]
field.setMFRotation(0, mf_rotation_expected)
ts_assert_doubles_equal(4, field.getMFRotation(0), mf_rotation_expected, "'wb_supervisor_field_set_mf_rotation' failed")

# MFNode
field = mf_test.getField("mfNode")
node = field.getMFNode(-1)
ts_assert_boolean_equal(node.getType() == Node.BALL_JOINT, "'wb_supervisor_field_get_mf_node' failed")

# the robot at its initial position before the first step
field = proto.getField("translation")
vector3_current = field.getSFVec3f()
ts_assert_vec3_equal(vector3_current[0], vector3_current[1], vector3_current[2], 0, 0, 0, "Robot not in initial position")

# SF tracking
field = box.getField("translation")
ts_assert_pointer_not_null(field, "Translation field is not found")
field.enableSFTracking(TIME_STEP)

for _ in range(10):
    robot.step(TIME_STEP)
    vector3_modified = field.getSFVec3f()
    vector3_expected = [0.123, 0, 0.7777]
    ts_assert_doubles_equal(3, vector3_modified, vector3_expected,
                            "Field tracking failed, should be [%lf, %lf, %lf] instead of [%lf, %lf, %lf]",
                            vector3_expected[0], vector3_expected[1], vector3_expected[2], vector3_modified[0],
                            vector3_modified[1], vector3_modified[2])
field.disableSFTracking()

# writing back a translation read earlier
for _ in range(10):
    robot.step(TIME_STEP)
vector3_start = list(field.getSFVec3f())
for _ in range(10):
    robot.step(TIME_STEP)
vector3_end = list(field.getSFVec3f())
field.setSFVec3f(vector3_start)
for _ in range(10):
    robot.step(TIME_STEP)
vector3_current = field.getSFVec3f()
vector3 = [vector3_current[k] - vector3_end[k] for k in range(3)]
ts_assert_vec3_in_delta(vector3[0], vector3[1], vector3[2], 0, 0, 0, 0.01,
                        "Moving robot reset translation test failed: error is (%f, %f, %f)", vector3[0], vector3[1],
                        vector3[2])

# a value set, read after two steps
field = box.getField("translation")
vector3_expected = [0.456, 0.0, 0.8888]
field.setSFVec3f(vector3_expected)
robot.step(TIME_STEP)
robot.step(TIME_STEP)
vector3_modified = field.getSFVec3f()
ts_assert_doubles_equal(3, vector3_modified, vector3_expected, "Delayed 'wb_supervisor_field_set_sf_vec3f' failed")

# removing a tracked node
robot.step(TIME_STEP)
field = box.getField("translation")
field.enableSFTracking(TIME_STEP)
robot.step(2 * TIME_STEP)
box.remove()
robot.step(2 * TIME_STEP)
field.getSFVec3f()
field.disableSFTracking()

# an internal field reference made invalid by the PROTO's regeneration
internal_field_type = internal_field.getType()
print("internal_field_type %d" % internal_field_type)
ts_assert_int_equal(internal_field_type, 0, "Internal field reference is invalid after PROTO regeneration")
internal_field = proto.getProtoField("cpuConsumption")
print("internal_field %s" % internal_field)
ts_assert_pointer_not_null(internal_field, "Node reference should be invalid after PROTO regeneration")
d = internal_field.getSFFloat()
ts_assert_double_equal(d, 1.11, "Returned value should be 1.11 and not %f", d)

# two MFFloat writes in one step
robot.step(TIME_STEP)
field = mf_test.getField("mfFloat")
field.setMFFloat(0, 1.0)
field.setMFFloat(1, 2.0)
mf_float_expected = field.getMFFloat(0)
ts_assert_double_equal(mf_float_expected, 1.0, "Consecutive wb_supervisor_field_set_mf_float: first set instruction "
                       "failed.")
robot.step(TIME_STEP)
mf_float_expected = field.getMFFloat(1)
ts_assert_double_equal(mf_float_expected, 2.0, "Consecutive wb_supervisor_field_set_mf_float: second set instruction "
                       "failed.")
robot.step(TIME_STEP)

# fields by index
fields_count = mf_test.getNumberOfFields()
ts_assert_int_equal(fields_count, 9, "Number of fields of MF_FIELDS node is wrong")
field0 = mf_test.getFieldByIndex(0)
ts_assert_string_equal(field0.getName(), "mfBool", "Name of first field of MF_FIELDS node is wrong")
ts_assert_boolean_equal(field0 == mf_test.getField("mfBool"), "Different WbFieldRef returned for the same 'mfBool' field.")
field2 = mf_test.getFieldByIndex(2)
ts_assert_string_equal(field2.getName(), "mfFloat", "Name of third field of MF_FIELDS node is wrong")
ts_assert_boolean_equal(field2 == mf_test.getField("mfFloat"),
                        "Different WbFieldRef returned for the same 'mfFloat' field.")
field8 = mf_test.getFieldByIndex(fields_count - 1)
ts_assert_string_equal(field8.getName(), "mfNode", "Name of last field of MF_FIELDS node is wrong")
ts_assert_boolean_equal(field8 == mf_test.getField("mfNode"), "Different WbFieldRef returned for the same 'mfNode' field.")
field_invalid = mf_test.getFieldByIndex(-1)
ts_assert_pointer_null(field_invalid, "It should not be possible to retrieve a field using a negative index")
field_invalid = mf_test.getFieldByIndex(fields_count)
ts_assert_pointer_null(field_invalid, "It should not be possible to retrieve a field using an out of range index")

proto_fields_count = mf_test.getProtoNumberOfFields()
ts_assert_int_equal(proto_fields_count, 17, "Number of PROTO internal fields of MF_FIELDS node is wrong")
field0 = mf_test.getProtoFieldByIndex(0)
ts_assert_string_equal(field0.getName(), "translation", 'Name of first PROTO internal field of MF_FIELDS node is wrong: '
                       '"%s" should be "translation"', field0.getName())
field2 = mf_test.getProtoFieldByIndex(2)
ts_assert_string_equal(field2.getName(), "children", 'Name of third PROTO internal field of MF_FIELDS node is wrong: '
                       '"%s" should be "children"', field2.getName())
field8 = mf_test.getProtoFieldByIndex(fields_count - 1)
ts_assert_string_equal(field8.getName(), "boundingObject", 'Name of ninth PROTO internal field of MF_FIELDS node is '
                       'wrong: "%s" should be "boundingObject"', field8.getName())
field_invalid = mf_test.getProtoFieldByIndex(-5)
ts_assert_pointer_null(field_invalid, "It should not be possible to retrieve a PROTO internal field using a negative "
                       "index")
field_invalid = mf_test.getProtoFieldByIndex(proto_fields_count)
ts_assert_pointer_null(field_invalid, "It should not be possible to retrieve a PROTO internal field using an out of range "
                       "index")

robot.step(TIME_STEP)

# switching the robot's 'supervisor' field off
self_node = robot.getSelf()
supervisor_field = self_node.getField("supervisor")
ts_assert_boolean_equal(supervisor_field.getSFBool(), "'supervisor' field should be true")
ts_assert_boolean_equal(robot.getSupervisor(), "'wb_robot_get_supervisor' field should return true")
supervisor_field.setSFBool(False)
robot.step(TIME_STEP)

ts_assert_boolean_equal(not robot.getSupervisor(), "'wb_robot_get_supervisor' field should return false")
self_id = self_node.getId()
ts_assert_int_equal(self_id, -1, "Returned value for 'wb_supervisor_node_get_id' field should be '-1' when 'supervisor' "
                    "field is set to FALSE and not '%d'", self_id)

ts_send_success()
