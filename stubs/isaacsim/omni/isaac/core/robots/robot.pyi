from omni.isaac.core.robots import Robot as Robot
