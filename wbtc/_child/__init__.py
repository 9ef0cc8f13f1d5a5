"""Put on a controller process's PYTHONPATH: holds the `controller` package Webots controllers import."""
