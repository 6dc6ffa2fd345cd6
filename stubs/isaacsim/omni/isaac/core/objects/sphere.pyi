from omni.isaac.core.objects import DynamicSphere as DynamicSphere
from omni.isaac.core.objects import FixedSphere as FixedSphere
from omni.isaac.core.objects import VisualSphere as VisualSphere
