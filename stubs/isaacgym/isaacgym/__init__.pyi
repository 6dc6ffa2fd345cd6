from isaacgym import torch_utils as torch_utils
