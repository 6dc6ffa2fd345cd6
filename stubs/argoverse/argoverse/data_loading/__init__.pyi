from argoverse.data_loading import pose_loader as pose_loader
