from typing import Annotated

from geolint.knowledge.markers import LaunchNode

class ExecuteProcess:
    """Source: ros2/launch launch/launch/actions/execute_process.py (jazzy), `ExecuteProcess.__init__(self, *, cmd:
    Iterable[SomeSubstitutionsType], prefix=None, name=None, cwd=None, env=None, additional_env=None, shell=False,
    ...)`: ":param: cmd A list where the first item is the executable and the rest are arguments to the executable,
    each item may be a string or a list of strings and Substitutions to be resolved at runtime"."""

    def __init__(self, *, cmd: Annotated[list[str], LaunchNode.COMMAND], **kwargs: object) -> None: ...
