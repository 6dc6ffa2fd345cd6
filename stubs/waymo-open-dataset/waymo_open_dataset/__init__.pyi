# waymo_open_dataset (1.6.7) has no __init__.py: `from waymo_open_dataset import dataset_pb2, label_pb2` imports the modules
from waymo_open_dataset import dataset_pb2 as dataset_pb2, label_pb2 as label_pb2
