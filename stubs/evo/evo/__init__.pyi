from evo import core as core
