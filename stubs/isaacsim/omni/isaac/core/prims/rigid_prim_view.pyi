from omni.isaac.core.prims import RigidPrimView as RigidPrimView
