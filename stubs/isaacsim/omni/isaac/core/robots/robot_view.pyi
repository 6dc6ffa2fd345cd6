from omni.isaac.core.robots import RobotView as RobotView
