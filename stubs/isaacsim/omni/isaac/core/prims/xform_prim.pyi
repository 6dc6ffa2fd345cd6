from omni.isaac.core.prims import XFormPrim as XFormPrim
