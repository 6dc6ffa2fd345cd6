from omni.isaac.core.prims import GeometryPrim as GeometryPrim
