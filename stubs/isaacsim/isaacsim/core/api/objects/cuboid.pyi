from isaacsim.core.api.objects import DynamicCuboid as DynamicCuboid
from isaacsim.core.api.objects import FixedCuboid as FixedCuboid
from isaacsim.core.api.objects import VisualCuboid as VisualCuboid
