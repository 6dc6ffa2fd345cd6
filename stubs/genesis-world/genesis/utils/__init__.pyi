from genesis.utils import geom as geom
