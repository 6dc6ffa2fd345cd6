from geometry_msgs import msg as msg
