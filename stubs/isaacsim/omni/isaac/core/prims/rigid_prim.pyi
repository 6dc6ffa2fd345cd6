from omni.isaac.core.prims import RigidPrim as RigidPrim
