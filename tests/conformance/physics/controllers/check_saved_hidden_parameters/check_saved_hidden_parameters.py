"""Port of Webots' tests/physics/controllers/check_saved_hidden_parameters: a Youbot moves its arm, then the world is
saved and reloaded three times (the arm's pose survives only through the saved hidden joint parameters); at the end a
camera must still see the arm where it was moved (white background pixels around it)."""

from controller import Camera, Supervisor
from ts_assertion import ts_assert_int_equal, ts_send_success, ts_setup

TEMP_WORLD_FILE_PATH = "../../worlds/check_saved_hidden_parameters_temp.wbt"


def check_robot_position(time_step):
    camera = robot.getDevice("camera")
    camera.enable(time_step)
    robot.step(time_step)
    image_width = camera.getWidth()
    image_height = camera.getHeight()
    image = camera.getImage()
    for x in range(image_width):
        for y in range(image_height):
            if y < 12 or (y < 28 and (x < 10 or x > 23)):
                value = Camera.imageGetGray(image, image_width, x, y)
                ts_assert_int_equal(value, 255, "Wrong arm position: camera image pixel at [x=%d, y=%d] should be "
                                    "white.", x, y)


robot = Supervisor()

time_step = int(robot.getBasicTimeStep())
custom_data = robot.getCustomData()

if custom_data == "init":
    # let the arm move, then save and reload
    robot.step(32 * time_step)

    robot.setCustomData("save1")

    robot_node = robot.getFromDef("ROBOT")
    controller_field = robot_node.getField("controller")
    controller_field.setSFString("<generic>")

    robot.worldSave(TEMP_WORLD_FILE_PATH)
    robot.worldLoad(TEMP_WORLD_FILE_PATH)

elif custom_data == "save1":
    robot.setCustomData("save2")
    robot.worldSave(TEMP_WORLD_FILE_PATH)
    robot.worldLoad(TEMP_WORLD_FILE_PATH)

elif custom_data == "save2":
    robot.setCustomData("test")
    robot.worldSave(TEMP_WORLD_FILE_PATH)
    robot.worldLoad(TEMP_WORLD_FILE_PATH)

elif custom_data == "test":
    ts_setup(robot, "check_saved_hidden_parameter")

    check_robot_position(time_step)

    ts_send_success()
