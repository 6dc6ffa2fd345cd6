from isaacsim.core.api.objects import DynamicSphere as DynamicSphere
from isaacsim.core.api.objects import FixedSphere as FixedSphere
from isaacsim.core.api.objects import VisualSphere as VisualSphere
