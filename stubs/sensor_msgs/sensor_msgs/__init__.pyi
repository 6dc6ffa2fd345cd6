from sensor_msgs import msg as msg
