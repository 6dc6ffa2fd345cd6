from mujoco_py import functions as functions
