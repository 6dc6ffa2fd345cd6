from omni.isaac.core.prims import XFormPrimView as XFormPrimView
