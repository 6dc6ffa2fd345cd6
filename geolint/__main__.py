"""`python -m geolint` is the `geolint` command."""

import sys

from geolint.cli import main

sys.exit(main())
