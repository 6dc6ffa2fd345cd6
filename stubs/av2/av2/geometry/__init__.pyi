from av2.geometry import geometry as geometry, se3 as se3
