from av2 import geometry as geometry
