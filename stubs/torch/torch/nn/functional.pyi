from typing import Annotated

from geolint.knowledge.markers import ArrayOperation

def pad(input: object, pad: object, mode: str = ..., value: object = ...) -> Annotated[object, ArrayOperation.PAD_LAST_AXIS_FIRST]:
    """Source: torch torch.nn.functional.pad (PyTorch 2.x documentation): "The padding size by which to pad some dimensions of input are described starting from the last dimension and moving forward ... to pad only the last dimension of the input tensor, then pad has the form (padding_left, padding_right)"; `value`: "fill value for 'constant' padding. Default: 0"."""

# Learned-feature operations: each returns a feature map computed from (sampled at, pooled over) its input,
# never coordinates.

def grid_sample(input: object, grid: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.grid_sample (PyTorch 2.x documentation): "Given an input and a flow-field grid, computes the output using input values and pixel locations from grid"."""

def interpolate(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.interpolate (PyTorch 2.x documentation): "Down/up samples the input"."""

def conv1d(input: object, weight: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.conv1d (PyTorch 2.x documentation): "Applies a 1D convolution over an input signal composed of several input planes"."""

def conv2d(input: object, weight: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.conv2d (PyTorch 2.x documentation): "Applies a 2D convolution over an input image composed of several input planes"."""

def conv3d(input: object, weight: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.conv3d (PyTorch 2.x documentation): "Applies a 3D convolution over an input image composed of several input planes"."""

def conv_transpose2d(input: object, weight: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.conv_transpose2d (PyTorch 2.x documentation): "Applies a 2D transposed convolution operator over an input image"."""

def linear(input: object, weight: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.linear (PyTorch 2.x documentation): "Applies a linear transformation to the incoming data: y = xA^T + b", a layer's learned weights."""

def relu(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.relu (PyTorch 2.x documentation): "Applies the rectified linear unit function element-wise"."""

def leaky_relu(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.leaky_relu (PyTorch 2.x documentation): "Applies element-wise, LeakyReLU(x) = max(0, x) + negative_slope * min(0, x)"."""

def gelu(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.gelu (PyTorch 2.x documentation): "Apply Gaussian Error Linear Units function"."""

def silu(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.silu (PyTorch 2.x documentation): "Apply the Sigmoid Linear Unit (SiLU) function, element-wise"."""

def sigmoid(input: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.sigmoid (PyTorch 2.x documentation): "Applies the element-wise function Sigmoid(x) = 1 / (1 + exp(-x))"."""

def softmax(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.softmax (PyTorch 2.x documentation): "Apply a softmax function", weights that sum to 1."""

def log_softmax(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.log_softmax (PyTorch 2.x documentation): "Apply a softmax followed by a logarithm"."""

def embedding(input: object, weight: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.embedding (PyTorch 2.x documentation): "Generate a simple lookup table that looks up embeddings in a fixed dictionary and size"."""

def layer_norm(input: object, normalized_shape: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.layer_norm (PyTorch 2.x documentation): "Apply Layer Normalization for last certain number of dimensions"."""

def batch_norm(input: object, running_mean: object, running_var: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.batch_norm (PyTorch 2.x documentation): "Apply Batch Normalization for each channel across a batch of data"."""

def group_norm(input: object, num_groups: int, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.group_norm (PyTorch 2.x documentation): "Apply Group Normalization for last certain number of dimensions"."""

def dropout(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.dropout (PyTorch 2.x documentation): "During training, randomly zeroes some elements of the input tensor with probability p"."""

def max_pool1d(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.max_pool1d (PyTorch 2.x documentation): "Applies a 1D max pooling over an input signal composed of several input planes"."""

def max_pool2d(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.max_pool2d (PyTorch 2.x documentation): "Applies a 2D max pooling over an input signal composed of several input planes"."""

def max_pool3d(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.max_pool3d (PyTorch 2.x documentation): "Applies a 3D max pooling over an input signal composed of several input planes"."""

def avg_pool2d(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.avg_pool2d (PyTorch 2.x documentation): "Applies 2D average-pooling operation in kH x kW regions"."""

def adaptive_avg_pool2d(input: object, output_size: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.adaptive_avg_pool2d (PyTorch 2.x documentation): "Apply a 2D adaptive average pooling over an input signal composed of several input planes"."""

def adaptive_max_pool1d(input: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.adaptive_max_pool1d (PyTorch 2.x documentation): "Applies a 1D adaptive max pooling over an input signal composed of several input planes"."""

def scaled_dot_product_attention(query: object, key: object, value: object, *args: object, **kwargs: object) -> Annotated[object, ArrayOperation.FEATURES]:
    """Source: torch torch.nn.functional.scaled_dot_product_attention (PyTorch 2.x documentation): "Computes scaled dot product attention on query, key and value tensors"."""
