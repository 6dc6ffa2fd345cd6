from sensor_msgs.msg import NavSatFix as NavSatFix
