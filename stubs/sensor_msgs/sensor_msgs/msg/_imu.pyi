from sensor_msgs.msg import Imu as Imu
