from torchvision import transforms as transforms
