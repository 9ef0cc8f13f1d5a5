"""The compile stage: an expanded scene to a MuJoCo model and the runtime DeviceTable."""
