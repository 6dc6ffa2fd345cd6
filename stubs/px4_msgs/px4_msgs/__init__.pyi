from px4_msgs import msg as msg
