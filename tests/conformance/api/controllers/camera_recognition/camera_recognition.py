"""Port of Webots' tests/api/controllers/camera_recognition: recognized objects of planar, spherical and cylindrical
cameras (count, occlusion, model, colours, pose, size and position on image) and the segmentation image.

The stored world is the one of Webots' PR #6403 (October 2023), which added the "perpendicular box" to the objects every
camera recognises; the only upstream controller in the search index predates it (6 visible solids). This port follows
the controller of that PR, as kept in omnilink-tech/omnisim (a Webots fork,
tests/api/controllers/camera_recognition/camera_recognition.c): 7 visible solids, and the box's pose checked in the
spherical and cylindrical cameras.
"""

import os

from controller import Camera, Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_boolean_not_equal,
    ts_assert_color_in_delta,
    ts_assert_double_is_bigger,
    ts_assert_doubles_in_delta,
    ts_assert_int_equal,
    ts_assert_int_in_delta,
    ts_assert_integers_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32
VISIBLE_SOLID_NUMBER = 7

VISIBLE_SOLID_MODELS = ("visible sphere", "visible box", "sub solid", "visible capsule", "composed solid",
                        "visible sphere without BO", "perpendicular box")

OCCLUDED_SOLID_MODEL = "occluded box"

robot = Supervisor()
ts_setup(robot)

camera = robot.getDevice("camera")
camera.enable(TIME_STEP)
camera.recognitionEnable(TIME_STEP)

camera_spherical = robot.getDevice("spherical")
camera_spherical.enable(TIME_STEP)
camera_spherical.recognitionEnable(TIME_STEP)

camera_cylindrical = robot.getDevice("cylindrical")
camera_cylindrical.enable(TIME_STEP)
camera_cylindrical.recognitionEnable(TIME_STEP)

robot.step(TIME_STEP)
object_number = camera.getRecognitionNumberOfObjects()
ts_assert_int_equal(object_number, VISIBLE_SOLID_NUMBER + 1,
                    "The planar camera should initially see %d objects and not %d (without occlusion).",
                    VISIBLE_SOLID_NUMBER + 1, object_number)

object_number = camera_spherical.getRecognitionNumberOfObjects()
ts_assert_int_equal(object_number, VISIBLE_SOLID_NUMBER + 4,
                    "The spherical camera should initially see %d objects and not %d (with occlusion).",
                    VISIBLE_SOLID_NUMBER + 4, object_number)

object_number = camera_cylindrical.getRecognitionNumberOfObjects()
ts_assert_int_equal(object_number, VISIBLE_SOLID_NUMBER + 2,
                    "The cylindrical camera should initially see %d objects and not %d (with occlusion).",
                    VISIBLE_SOLID_NUMBER + 2, object_number)

recognition_node = robot.getFromDef("RECOGNITION")
occlusion_field = recognition_node.getField("occlusion")
occlusion_field.setSFInt32(2)

ts_assert_boolean_equal(camera.hasRecognitionSegmentation(), "The Recognition.segmentation field should be set to TRUE.")
image = camera.getRecognitionSegmentationImage()
ts_assert_boolean_equal(image is None, "No segmentation image should be returned if segmentaton is disabled.")

robot.step(TIME_STEP)

camera.enableRecognitionSegmentation()

robot.step(TIME_STEP)
ts_assert_boolean_equal(camera.isRecognitionSegmentationEnabled(),
                        "The Recognition.segmentation functionality should be enabled.")
image = camera.getRecognitionSegmentationImage()
ts_assert_boolean_not_equal(
    image is None, "The camera segmentation image should not be NULL after enabling the segmented image generation.")
width = camera.getWidth()
red = Camera.imageGetRed(image, width, 215, 124)
ts_assert_int_in_delta(red, 193, 5, "Image should contain a red sphere at (215, 124): found red channel %d expected %d.", red,
                       193)
red = Camera.imageGetRed(image, width, 35, 71)
ts_assert_int_in_delta(
    red, 255, 5, "Image should contain a red L shaped geometry at (35, 71): found red channel %d expected %d.", red, 255)
# As in the C original, the three channels here are all read with the red getter.
red = Camera.imageGetRed(image, width, 95, 77)
green = Camera.imageGetRed(image, width, 95, 77)
blue = Camera.imageGetRed(image, width, 95, 77)
ts_assert_color_in_delta(red, green, blue, 0, 0, 0, 2,
                         "Image should not contain any object at (95, 77): found color (%d, %d, %d) expected (%d, %d, %d).",
                         red, green, blue, 0, 0, 0)
red = Camera.imageGetRed(image, width, 52, 124)
green = Camera.imageGetGreen(image, width, 52, 124)
blue = Camera.imageGetBlue(image, width, 52, 124)
ts_assert_color_in_delta(red, green, blue, 0, 0, 255, 5,
                         "Image should contain a blue sphere at (54, 124)): found color (%d, %d, %d) expected (%d, %d, %d).",
                         red, green, blue, 0, 0, 255)

ts_assert_boolean_equal(
    camera.saveRecognitionSegmentationImage("segmentation.jpg", 100) != -1,
    "Camera recognition segmentation image did not save correctly (wb_camera_recognition_save_segmentation_image returned -1)")

robot.step(TIME_STEP)
camera.disableRecognitionSegmentation()
image = camera.getRecognitionSegmentationImage()
ts_assert_boolean_equal(image is None, "No segmentation image should be returned if segmentation is disabled.")

if os.path.exists("segmentation.jpg"):
    os.remove("segmentation.jpg")

robot.step(TIME_STEP)
ts_assert_boolean_not_equal(camera.isRecognitionSegmentationEnabled(),
                            "The Recognition.segmentation functionality should be disabled.")
segmentation_field = recognition_node.getField("segmentation")
segmentation_field.setSFBool(False)

robot.step(TIME_STEP)

ts_assert_boolean_not_equal(camera.hasRecognitionSegmentation(),
                            "Camera recognition segmentation should be FALSE after changing the field value.")

robot.step(TIME_STEP)
object_number = camera.getRecognitionNumberOfObjects()
objects = camera.getRecognitionObjects()

ts_assert_int_equal(object_number, VISIBLE_SOLID_NUMBER,
                    "The camera should initially see %d objects and not %d (with occlusion).", VISIBLE_SOLID_NUMBER,
                    object_number)
sub_solid_index = 0
composed_solid_index = 0
for i in range(object_number):
    model = objects[i].getModel()
    if model == "visible sphere without BO":
        expected_position_on_image = (189, 41)
        position_on_image = objects[i].getPositionOnImage()
        ts_assert_integers_in_delta(
            2, position_on_image, expected_position_on_image, 1,
            "Image coordinate of the 'visible sphere without BO' solid is not correct: found (%d, %d), expected (%d, %d).",
            position_on_image[0], position_on_image[1], expected_position_on_image[0], expected_position_on_image[1])
    found = model in VISIBLE_SOLID_MODELS
    ts_assert_boolean_equal(found, "Object '%s' should not be visible.\n", model)
    node_ref = robot.getFromId(objects[i].getId())
    node_ref.remove()
    if model == "sub solid":
        sub_solid_index = i
    if model == "composed solid":
        composed_solid_index = i

sub_size = objects[sub_solid_index].getSizeOnImage()
composed_size = objects[composed_solid_index].getSizeOnImage()
sub_solid_size = float(sub_size[0] * sub_size[1])
composed_solid_size = float(composed_size[0] * composed_size[1])
ts_assert_double_is_bigger(composed_solid_size, sub_solid_size, "Object: '%s' should have a bigger pixel size than '%s'.",
                           objects[composed_solid_index].getModel(), objects[sub_solid_index].getModel())

# The perpendicular box, recognised with its pose by both panoramic cameras.
PERPENDICULAR_BOX_POSITION = [-0.528470, -1.191827, -0.105723]
PERPENDICULAR_BOX_ORIENTATION = [0.577352, -0.577349, 0.577350, 2.094393]
for panoramic, kind in ((camera_spherical, "spherical"), (camera_cylindrical, "cylindrical")):
    for recognized in panoramic.getRecognitionObjects():
        if recognized.getModel() != "perpendicular box":
            continue
        position = recognized.getPosition()
        ts_assert_doubles_in_delta(3, position, PERPENDICULAR_BOX_POSITION, 0.001,
                                   "Position of 'perpendicular box' is not correct for %s camera: found=(%f, %f, %f), "
                                   "expected=(%f, %f, %f).", kind, *position, *PERPENDICULAR_BOX_POSITION)
        orientation = recognized.getOrientation()
        ts_assert_doubles_in_delta(4, orientation, PERPENDICULAR_BOX_ORIENTATION, 0.001,
                                   "Orientation of 'perpendicular box' is not correct for %s camera: found=(%f, %f, %f, "
                                   "%f), expected=(%f, %f, %f, %f).", kind, *orientation, *PERPENDICULAR_BOX_ORIENTATION)

robot.step(TIME_STEP)

object_number = camera.getRecognitionNumberOfObjects()
objects = camera.getRecognitionObjects()

ts_assert_int_equal(object_number, 1, "The camera should see only 1 objects after removal of the initial objects and not %d.",
                    object_number)
ts_assert_int_equal(0 if objects[0].getModel() == OCCLUDED_SOLID_MODEL else 1, 0,
                    "The last remaining object should be '%s' and not '%s'.", OCCLUDED_SOLID_MODEL, objects[0].getModel())

number_of_colors = objects[0].getNumberOfColors()
ts_assert_int_equal(number_of_colors, 2, "The last remaining object should have 2 colors and not %d.", number_of_colors)
colors = objects[0].getColors()
red1 = int(colors[0] * 255)
green1 = int(colors[1] * 255)
blue1 = int(colors[2] * 255)
red2 = int(colors[3] * 255)
green2 = int(colors[4] * 255)
blue2 = int(colors[5] * 255)

ts_assert_color_in_delta(red1, green1, blue1, 0, 255, 0, 0, "Wrong first color for object '%s'.", objects[0].getModel())
ts_assert_color_in_delta(red2, green2, blue2, 255, 0, 255, 0, "Wrong second color for object '%s'.", objects[0].getModel())

segmentation_field.setSFBool(True)
robot.step(TIME_STEP)
camera.enableRecognitionSegmentation()
camera_spherical.enableRecognitionSegmentation()
camera_cylindrical.enableRecognitionSegmentation()
robot.step(TIME_STEP)
image = camera.getRecognitionSegmentationImage()
SOLID_X = 124
SOLID_Y = 200
red = Camera.imageGetRed(image, width, SOLID_X, SOLID_Y)
green = Camera.imageGetGreen(image, width, SOLID_X, SOLID_Y)
blue = Camera.imageGetBlue(image, width, SOLID_X, SOLID_Y)
ts_assert_color_in_delta(red, green, blue, 0, 255, 0, 2,
                         "Wrong green box segmentation color before changing the recognition color.")

green_box = robot.getFromDef("GREEN_BOX")
color_field = green_box.getField("recognitionColors")
color_field.setMFColor(0, [0.5, 0.5, 0.5])
robot.step(TIME_STEP)
image = camera.getRecognitionSegmentationImage()
red = Camera.imageGetRed(image, width, SOLID_X, SOLID_Y)
green = Camera.imageGetGreen(image, width, SOLID_X, SOLID_Y)
blue = Camera.imageGetBlue(image, width, SOLID_X, SOLID_Y)
ts_assert_color_in_delta(red, green, blue, 127, 127, 127, 2,
                         "Wrong green box segmentation color after changing the recognition color.")


def check_object(obj, label: str, position, orientation, size, size_on_image, position_on_image) -> None:
    """The pose, size and image placement checks the C original repeats for each object and camera."""
    p, o, s = obj.getPosition(), obj.getOrientation(), obj.getSize()
    ts_assert_doubles_in_delta(
        3, p, position, 0.001,
        "Position of %s is not correct: found=(%f, %f, %f), expected=(%f, %f, %f).",
        label, p[0], p[1], p[2], position[0], position[1], position[2])
    ts_assert_doubles_in_delta(
        4, o, orientation, 0.001,
        "Orientation of %s is not correct: found=(%f, %f, %f, %f), expected=(%f, %f, %f, %f).",
        label, o[0], o[1], o[2], o[3], orientation[0], orientation[1], orientation[2], orientation[3])
    ts_assert_doubles_in_delta(
        2, s, size, 0.001, "Size of %s is not correct: found=(%f, %f), expected=(%f, %f).",
        label, s[0], s[1], size[0], size[1])
    si = obj.getSizeOnImage()
    ts_assert_integers_in_delta(
        2, si, size_on_image, 1, "Size on image of %s is not correct: found=(%d, %d), expected=(%d, %d).",
        label, si[0], si[1], size_on_image[0], size_on_image[1])
    pi = obj.getPositionOnImage()
    ts_assert_integers_in_delta(
        2, pi, position_on_image, 1, "Position on image of %s is not correct: found=(%d, %d), expected=(%d, %d).",
        label, pi[0], pi[1], position_on_image[0], position_on_image[1])


INVISIBLE_CAPSULE_POSITION = (0.369, 1.650, 0.899)
INVISIBLE_CAPSULE_ORIENTATION = (0.577350, -0.577350, -0.577350, 2.094390)
INVISIBLE_CAPSULE_SIZE = (0.1, 0.1)
object_number = camera_spherical.getRecognitionNumberOfObjects()
ts_assert_int_equal(object_number, 4,
                    "The spherical camera should see only 4 objects after removal of the initial objects and not %d.",
                    object_number)
objects = camera_spherical.getRecognitionObjects()
image = camera_spherical.getRecognitionSegmentationImage()
for i in range(object_number):
    model = objects[i].getModel()
    if model == OCCLUDED_SOLID_MODEL:
        check_object(objects[i], "'occluded box' for spherical camera", (-0.550, 0.0, 0.429),
                     (0.577350, -0.577350, -0.577350, 2.094390), (0.1, 0.9), (146, 42), (128, 47))
        u, v = 69, 47
        red = Camera.imageGetRed(image, width, u, v)
        green = Camera.imageGetGreen(image, width, u, v)
        blue = Camera.imageGetBlue(image, width, u, v)
        ts_assert_color_in_delta(red, green, blue, 127, 127, 127, 2,
                                 "Wrong green box segmentation color in spherical camera image.")
    elif model == "invisible capsule":
        check_object(objects[i], "'invisble capsule' for spherical camera", INVISIBLE_CAPSULE_POSITION,
                     INVISIBLE_CAPSULE_ORIENTATION, INVISIBLE_CAPSULE_SIZE, (14, 28), (79, 102))

object_number = camera_cylindrical.getRecognitionNumberOfObjects()
ts_assert_int_equal(object_number, 3,
                    "The cylidrical camera should see only 3 objects after removal of the initial objects and not %d.",
                    object_number)
objects = camera_cylindrical.getRecognitionObjects()
image = camera_cylindrical.getRecognitionSegmentationImage()
for i in range(object_number):
    if objects[i].getModel() == "invisible capsule":
        check_object(objects[i], "'invisble capsule' for cylindrical camera", INVISIBLE_CAPSULE_POSITION,
                     INVISIBLE_CAPSULE_ORIENTATION, INVISIBLE_CAPSULE_SIZE, (6, 45), (12, 88))
        u, v = 13, 92
        red = Camera.imageGetRed(image, width, u, v)
        green = Camera.imageGetGreen(image, width, u, v)
        blue = Camera.imageGetBlue(image, width, u, v)
        ts_assert_color_in_delta(red, green, blue, 0, 0, 255, 2,
                                 "Wrong blue capsule segmentation color in cylindrical camera image.")

ts_send_success()
