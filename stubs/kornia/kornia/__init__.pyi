from kornia import geometry as geometry
