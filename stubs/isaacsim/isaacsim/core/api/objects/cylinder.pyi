from isaacsim.core.api.objects import DynamicCylinder as DynamicCylinder
from isaacsim.core.api.objects import FixedCylinder as FixedCylinder
from isaacsim.core.api.objects import VisualCylinder as VisualCylinder
