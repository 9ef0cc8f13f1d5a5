"""Port of Webots' tests/api/controllers/supervisor_field_import_mf_node: importMFNodeFromString adds a DEF Solid
and an IMPORTABLE EXTERNPROTO instance (Chair) to the root's children, found at once with getFromDef, the PROTO with
its 'color' parameter."""

from controller import Supervisor
from ts_assertion import ts_assert_pointer_not_null, ts_send_success, ts_setup

TIME_STEP = 32

SOLID_TEXT = ("DEF FLOOR Solid {\n"
              "  translation -0.5 0 0.5\n"
              "  rotation 1 0 0 -1.57079632679\n"
              "  children [\n"
              "    Shape {\n"
              "      geometry ElevationGrid {\n"
              "        color Color {\n"
              "          color [\n"
              "            0.803922 0.498039 0.298039\n"
              "            1 1 0\n"
              "          ]\n"
              "        }\n"
              "        colorPerVertex FALSE\n"
              "        xDimension 11\n"
              "        xSpacing 0.1\n"
              "        yDimension 11\n"
              "        ySpacing 0.1\n"
              "      }\n"
              "    }\n"
              "  ]\n"
              "  boundingObject Pose {\n"
              "    translation 0.5 0.5 0\n"
              "    children [\n"
              "      Plane {\n"
              "      }\n"
              "    ]\n"
              "  }\n"
              "}")

robot = Supervisor()
ts_setup(robot)

root = robot.getRoot()
ts_assert_pointer_not_null(root, "wb_supervisor_node_get_root() failed to return the root node.")

field = root.getField("children")
ts_assert_pointer_not_null(field, "wb_supervisor_node_get_field() failed to find the 'children' field.")

field.importMFNodeFromString(0, SOLID_TEXT)

floor = robot.getFromDef("FLOOR")
ts_assert_pointer_not_null(floor, "wb_supervisor_node_get_from_def() failed to find the 'DEF FLOOR' node.")

field.importMFNodeFromString(0, "DEF CHAIR Chair {}")
chair = robot.getFromDef("CHAIR")
ts_assert_pointer_not_null(chair, "wb_supervisor_node_get_from_def() failed to find the 'DEF CHAIR' node.")

color = chair.getField("color")
ts_assert_pointer_not_null(color, "wb_supervisor_node_get_field() failed to find the 'color' proto parameter.")

ts_send_success()
