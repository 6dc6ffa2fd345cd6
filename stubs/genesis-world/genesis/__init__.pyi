# genesis/__init__.py: `gs.morphs` is genesis.options.morphs
from genesis.options import morphs as morphs
