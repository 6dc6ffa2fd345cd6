from nav_msgs import msg as msg
