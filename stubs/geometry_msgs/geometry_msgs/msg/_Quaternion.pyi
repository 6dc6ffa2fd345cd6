from geometry_msgs.msg import Quaternion as Quaternion
