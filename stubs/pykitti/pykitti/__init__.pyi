# pykitti/__init__.py (0.3.1): `from pykitti.raw import raw` etc.; `pykitti.utils` is imported as a module
from pykitti import utils as utils
