from omni.isaac.core.objects import DynamicCone as DynamicCone
from omni.isaac.core.objects import FixedCone as FixedCone
from omni.isaac.core.objects import VisualCone as VisualCone
