from sensor_msgs_py import point_cloud2 as point_cloud2
