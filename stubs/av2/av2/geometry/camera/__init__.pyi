from av2.geometry.camera import pinhole_camera as pinhole_camera
