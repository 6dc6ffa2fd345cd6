from omni.isaac.core.objects import DynamicCapsule as DynamicCapsule
from omni.isaac.core.objects import FixedCapsule as FixedCapsule
from omni.isaac.core.objects import VisualCapsule as VisualCapsule
