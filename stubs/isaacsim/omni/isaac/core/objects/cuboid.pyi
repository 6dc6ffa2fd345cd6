from omni.isaac.core.objects import DynamicCuboid as DynamicCuboid
from omni.isaac.core.objects import FixedCuboid as FixedCuboid
from omni.isaac.core.objects import VisualCuboid as VisualCuboid
