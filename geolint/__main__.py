"""`python -m geolint` is the `geolint` command."""

from geolint.cli import main_and_exit

main_and_exit()
