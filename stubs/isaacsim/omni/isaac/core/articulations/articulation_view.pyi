from omni.isaac.core.articulations import ArticulationView as ArticulationView
