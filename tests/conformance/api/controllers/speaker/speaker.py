"""Port of Webots' tests/api/controllers/speaker: isSpeaking and isSoundPlaying before, during text-to-speech and
while a looped sound file plays."""

from controller import Robot, Speaker
from ts_assertion import ts_assert_boolean_equal, ts_send_success, ts_setup

TIME_STEP = 32
SOUND_FILE = "sound.wav"

robot = Robot()
ts_setup(robot)

speaker = robot.getDevice("speaker")

robot.step(TIME_STEP)

ts_assert_boolean_equal(not speaker.isSpeaking(), "wb_speaker_is_speaking should return false before starting TTS.")
ts_assert_boolean_equal(not speaker.isSoundPlaying(SOUND_FILE),
                        "wb_speaker_is_sound_playing should return false when the sound is not playing.")
ts_assert_boolean_equal(not speaker.isSoundPlaying(None),
                        "wb_speaker_is_sound_playing should return false when called with a NULL argument if TTS is not "
                        "running and no sound is playing.")

ts_assert_boolean_equal(speaker.setLanguage("en-US"), "Fail to set english for TTS.")
ts_assert_boolean_equal(speaker.setEngine("pico"),
                        "Fail to set the 'pico' engine for the TTS (should be available on every platforms).")

robot.step(TIME_STEP)

speaker.speak("Hello test suite!", 0.1)

ts_assert_boolean_equal(speaker.isSpeaking(), "wb_speaker_is_speaking should return true when TTS is running.")
ts_assert_boolean_equal(not speaker.isSoundPlaying(SOUND_FILE),
                        "wb_speaker_is_sound_playing should return false when the sound is not playing.")
ts_assert_boolean_equal(speaker.isSoundPlaying(None),
                        "wb_speaker_is_sound_playing should return true when called with a NULL argument if TTS is running.")

robot.step(TIME_STEP)

ts_assert_boolean_equal(speaker.isSpeaking(), "wb_speaker_is_speaking should return true when TTS is running.")
ts_assert_boolean_equal(not speaker.isSoundPlaying(SOUND_FILE),
                        "wb_speaker_is_sound_playing should return false when the sound is not playing.")

robot.step(TIME_STEP)

speaker.stop(None)
Speaker.playSound(speaker, speaker, SOUND_FILE, 0.1, 1.0, 0.0, True)

ts_assert_boolean_equal(not speaker.isSpeaking(), "wb_speaker_is_speaking should return false when TTS is not running.")
ts_assert_boolean_equal(speaker.isSoundPlaying(SOUND_FILE),
                        "wb_speaker_is_sound_playing should return true when the sound is playing.")
ts_assert_boolean_equal(
    speaker.isSoundPlaying(None),
    "wb_speaker_is_sound_playing should return true when called with a NULL argument when a sound is playing.")

robot.step(TIME_STEP)

ts_assert_boolean_equal(not speaker.isSpeaking(), "wb_speaker_is_speaking should return false when TTS is not running.")
ts_assert_boolean_equal(speaker.isSoundPlaying(SOUND_FILE),
                        "wb_speaker_is_sound_playing should return true when the sound is playing.")
ts_assert_boolean_equal(
    speaker.isSoundPlaying(None),
    "wb_speaker_is_sound_playing should return true when called with a NULL argument when a sound is playing.")

ts_send_success()
