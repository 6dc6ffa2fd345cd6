from isaacsim.core.api.objects import DynamicCapsule as DynamicCapsule
from isaacsim.core.api.objects import FixedCapsule as FixedCapsule
from isaacsim.core.api.objects import VisualCapsule as VisualCapsule
