from pytransform3d import batch_rotations as batch_rotations, rotations as rotations, transformations as transformations
