from isaacsim.core.api.objects import DynamicCone as DynamicCone
from isaacsim.core.api.objects import FixedCone as FixedCone
from isaacsim.core.api.objects import VisualCone as VisualCone
