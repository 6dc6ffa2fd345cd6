"""One module per `geolint` subcommand, each with `add_arguments(parser)` and `run(args) -> int`."""
