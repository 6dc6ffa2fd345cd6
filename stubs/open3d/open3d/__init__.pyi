from open3d import geometry as geometry
