from argoverse import data_loading as data_loading, utils as utils
