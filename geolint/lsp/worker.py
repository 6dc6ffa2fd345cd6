"""One lint worker of the language server (`python -m geolint.lsp.worker`; see workers.py).

Reads pickled `(function, args, kwargs)` jobs from stdin and writes pickled `("ok", result)` or
`("error", traceback)` answers to what was stdout. Anything the linter prints goes to stderr, so it
cannot corrupt the answers. Exits when the server closes the pipe.
"""

from __future__ import annotations

import os
import pickle
import sys
import traceback
from typing import Any, Callable

from geolint import api, history
from geolint.factbase import conventions, ros_packages, tf_workspace

JOBS: dict[str, Callable[..., Any]] = {"lint_text": api.lint_text, "fix_text": api.fix_text}


def main() -> None:
    requests = sys.stdin.buffer
    answers = os.fdopen(os.dup(sys.stdout.fileno()), "wb")
    os.dup2(sys.stderr.fileno(), sys.stdout.fileno())  # stray prints go to the log, not the channel
    while True:
        try:
            function, args, kwargs = pickle.load(requests)
        except EOFError:
            return
        # a long-lived worker: what the project's files say about names is asked again for every job
        # (each file's votes are reused while its stat is unchanged, so only edited files are read)
        conventions.forget_project_totals()
        ros_packages.forget_packages()  # and what each ROS package's files say about its frame ids
        tf_workspace.forget_projects()  # and the tf tree each project's files state
        history.forget()  # and each repository's HEAD (its mined fixes stay cached by commit)
        try:
            answer: tuple[str, Any] = ("ok", JOBS[function](*args, **kwargs))
        except Exception:
            answer = ("error", traceback.format_exc())
        pickle.dump(answer, answers, protocol=pickle.HIGHEST_PROTOCOL)
        answers.flush()


if __name__ == "__main__":
    main()
