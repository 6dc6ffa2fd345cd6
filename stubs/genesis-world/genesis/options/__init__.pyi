from genesis.options import morphs as morphs
