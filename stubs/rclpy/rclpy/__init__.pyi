# rclpy/rclpy/__init__.py: the package re-exports nothing of Node's; `rclpy.node.Node` is imported by name
