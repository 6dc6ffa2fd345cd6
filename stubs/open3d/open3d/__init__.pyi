from open3d import geometry as geometry
from open3d import pipelines as pipelines
