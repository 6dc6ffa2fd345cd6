from omni.isaac.core.objects import DynamicCylinder as DynamicCylinder
from omni.isaac.core.objects import FixedCylinder as FixedCylinder
from omni.isaac.core.objects import VisualCylinder as VisualCylinder
