from omni.isaac.core.prims import GeometryPrimView as GeometryPrimView
