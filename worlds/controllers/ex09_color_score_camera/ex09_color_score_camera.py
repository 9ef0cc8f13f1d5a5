"""Example 9 with a real colour score: the lesson's linear model y = 0.2x - 1, where x is computed
from the camera image instead of the lesson's placeholder `color_score = 3`.
The score goes from 0 (red) to 5 (green): it is the hue of the mean colour of the 3x3 pixels at the
centre of the image (as in example 8), 0 degrees for red, 60 for yellow, 120 for green, scaled to
0..5 (hues past green count as 5, magenta-reds below red as 0; a grey patch, without hue, scores
2.5). The hue does not change when light adds the same amount to the three channels, so shading
and highlights do not move the score. Written for wbtc next to the lesson's file
(controllers/ex09_color_score_speed); it prints the score and speed at every step."""
from controller import Robot, Camera

robot = Robot()
timestep = int(robot.getBasicTimeStep())

camera = robot.getDevice('camera')
camera.enable(timestep)

left_motor = robot.getDevice('left wheel motor')
right_motor = robot.getDevice('right wheel motor')
left_motor.setPosition(float('inf'))
right_motor.setPosition(float('inf'))
left_motor.setVelocity(0)
right_motor.setVelocity(0)


def colour_score(image, width, height):
    """0 (red) .. 5 (green) from the hue of the central 3x3 pixels."""
    centerX = width // 2
    centerY = height // 2
    red = green = blue = 0
    for dx in range(-1, 2):
        for dy in range(-1, 2):
            red += camera.imageGetRed(image, width, centerX + dx, centerY + dy) / 9
            green += camera.imageGetGreen(image, width, centerX + dx, centerY + dy) / 9
            blue += camera.imageGetBlue(image, width, centerX + dx, centerY + dy) / 9
    high = max(red, green, blue)
    chroma = high - min(red, green, blue)
    if chroma < 1:
        return 2.5
    if high == red:
        hue = 60 * (green - blue) / chroma
        if hue < 0:
            return 0.0
    elif high == green:
        hue = 60 * (2 + (blue - red) / chroma)
    else:
        hue = 60 * (4 + (red - green) / chroma)
    return 5 * min(hue, 120) / 120


while robot.step(timestep) != -1:
    image = camera.getImage()
    color_score = colour_score(image, camera.getWidth(), camera.getHeight())
    predicted_speed = 0.2 * color_score - 1
    predicted_speed = max(-10, min(10, predicted_speed))
    left_motor.setVelocity(predicted_speed)
    right_motor.setVelocity(predicted_speed)
    print(f"colour score: {color_score:.2f}, speed: {predicted_speed:.2f}")
