from pytorch3d import transforms as transforms
