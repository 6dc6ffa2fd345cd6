from evo.core import trajectory as trajectory, transformations as transformations
