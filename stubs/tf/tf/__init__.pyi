# tf/src/tf/__init__.py: `from listener import Transformer, TransformListener`, `from broadcaster import TransformBroadcaster`
from tf.broadcaster import TransformBroadcaster as TransformBroadcaster
from tf.listener import TransformListener as TransformListener
