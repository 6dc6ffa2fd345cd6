from omni.isaac.core.articulations import Articulation as Articulation
