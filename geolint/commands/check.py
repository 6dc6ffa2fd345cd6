"""`geolint check [PATH ...]`: lint files and folders (or stdin), print findings, optionally fix them.

Exit codes: 0 nothing to report, 1 a finding of severity error or warning (or, with
`--exit-non-zero-on-fix`, a file fixed), 2 a usage, config or internal error; info and hint
findings are printed but leave the exit code alone. Findings go to stdout (or `--output FILE`) in
the chosen format. The human formats' summary (text, concise, full) follows the findings on
stdout, so a piped CI log reads top to bottom; with a machine format or `--output` it goes to
stderr, so stdout stays machine-readable. Progress, warnings and errors go to stderr.

Each file is linted with the nearest pyproject.toml that has a `[tool.geolint]` table, found from
the file's own folder (`--config FILE` names one for all): two projects on one command line each
keep their config.
"""

from __future__ import annotations

import argparse
import difflib
import os
import sys
import time
from collections import Counter
from dataclasses import replace
from pathlib import Path
from typing import Callable, Sequence

from geolint import api
from geolint.cli import EXIT_ERROR, EXIT_FINDINGS, EXIT_OK
from geolint.config import ConfigError, load_config, nearest_pyproject, parse_selector_list, with_overrides
from geolint.files import SourceFile
from geolint.lint_types import Config, Finding, Severity
from geolint.output import FORMATS, render
from geolint.terminal import ProgressBar, show_progress, use_color

FORMAT_VARIABLE = "GEOLINT_OUTPUT_FORMAT"
# Formats read by people: the summary follows the findings on stdout, and a terminal gets colour.
HUMAN_FORMATS = ("text", "concise", "full")
# Severities that fail a run (exit 1); info and hint findings are shown but do not.
FAILING = (Severity.ERROR, Severity.WARNING)
STDIN = Path("-")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("paths", nargs="*", type=Path, metavar="PATH", help="files or folders to lint (default: .), or - for stdin")
    parser.add_argument("--config", type=Path, metavar="FILE", help="use this pyproject.toml instead of the nearest one")
    parser.add_argument("--select", metavar="CODES", help="comma-separated codes or prefixes to enable (replaces the config's)")
    parser.add_argument("--extend-select", metavar="CODES", help="comma-separated codes or prefixes to enable as well (adds to the config's)")
    parser.add_argument("--ignore", metavar="CODES", help="comma-separated codes or prefixes to disable (adds to the config's)")
    parser.add_argument("--exclude", action="append", metavar="PATTERNS", help="comma-separated gitignore-style patterns to skip, replacing the config's `exclude` and the defaults")
    parser.add_argument("--extend-exclude", action="append", metavar="PATTERNS", help="comma-separated gitignore-style patterns to skip as well")
    parser.add_argument(
        "--output-format", "--format", dest="format", choices=FORMATS, default=_default_format(),
        help=f"output format (default: text, or ${FORMAT_VARIABLE})",
    )  # fmt: skip
    parser.add_argument("--output", type=Path, metavar="FILE", help="write findings to FILE instead of stdout")
    parser.add_argument("--statistics", action="store_true", help="print how often each code occurs instead of the findings")
    parser.add_argument("--exit-zero", action="store_true", help="exit 0 even when there are findings")
    parser.add_argument("--stdin-filename", metavar="PATH", help="the path of the file read from stdin (its config, per-file-ignores, display)")
    parser.add_argument("--watch", "-w", action="store_true", help="check again whenever a file or a config changes (Ctrl-C stops)")
    parser.add_argument("--jobs", "-j", type=_positive_int, metavar="N", help="worker processes (default: all cores)")
    parser.add_argument("--no-cache", action="store_true", help="neither read nor write the findings cache")
    parser.add_argument("--cache-dir", type=Path, metavar="DIR", help="where to keep the cache (default: <root>/.geolint_cache)")
    parser.add_argument("--force-exclude", action="store_true", help="apply excludes to files named on the command line too")
    parser.add_argument("--history", action="store_true", default=None, help="also report copies of statements the repository's git history fixed elsewhere (GEO401)")
    parser.add_argument("--history-limit", type=_positive_int, metavar="N", help="with --history: read at most the N newest commits (default: the config's, 1000)")
    fixing = parser.add_argument_group("fixes")
    fixing.add_argument("--fix", action="store_true", help="apply safe fixes in place (stdin: print the fixed text)")
    fixing.add_argument("--unsafe-fixes", action="store_true", help="with --fix or --diff, apply unsafe fixes too")
    fixing.add_argument("--diff", action="store_true", help="print the fixes as unified diffs; change no file")
    fixing.add_argument("--show-fixes", action="store_true", help="show the lines each fix changes; with --fix, list the findings fixed")
    fixing.add_argument("--exit-non-zero-on-fix", action="store_true", help="exit 1 when --fix changed a file")
    adoption = parser.add_argument_group("adopting geolint on existing code")
    adoption.add_argument("--write-baseline", type=Path, metavar="FILE", help="record the current findings in FILE and exit 0")
    adoption.add_argument("--baseline", type=Path, metavar="FILE", help="report only findings that FILE does not record")
    adoption.add_argument("--add-noqa", action="store_true", help="add a `# geolint: ignore[...]` comment for every finding")
    talk = parser.add_mutually_exclusive_group()
    talk.add_argument("--quiet", "-q", action="store_true", help="print findings only (no summary, no progress)")
    talk.add_argument("--verbose", "-v", action="store_true", help="also print config, file and cache counts, timing")


def _default_format() -> str:
    chosen = os.environ.get(FORMAT_VARIABLE, "text")
    return chosen if chosen in FORMATS else "text"  # an unknown value is reported by `run`


def _positive_int(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError("must be at least 1")
    return value


def run(args: argparse.Namespace) -> int:
    problem = _usage_problem(args)
    if problem is not None:
        _error(problem)
        return EXIT_ERROR
    if args.watch:
        from geolint.commands.watch import watch

        return watch(args, check_once)
    return check_once(args)


def _reads_stdin(args: argparse.Namespace) -> bool:
    return STDIN in args.paths or (bool(args.stdin_filename) and not args.paths)


def _usage_problem(args: argparse.Namespace) -> str | None:
    """What is wrong with the options together (argparse checks each alone), or None."""
    chosen = os.environ.get(FORMAT_VARIABLE)
    if chosen is not None and chosen not in FORMATS:
        return f"${FORMAT_VARIABLE}: unknown output format {chosen!r} (choose one of {', '.join(FORMATS)})"
    if _reads_stdin(args):
        if args.paths not in ([], [STDIN]):
            return "`-` (stdin) cannot be combined with other paths"
        for option, given in (("--watch", args.watch), ("--add-noqa", args.add_noqa), ("--write-baseline", args.write_baseline)):
            if given:
                return f"{option} cannot be used with stdin"
    return None


def check_once(args: argparse.Namespace) -> int:
    """One `geolint check` run: lint, report, return the exit code."""
    started = time.perf_counter()
    if _reads_stdin(args):
        return _check_stdin(args, started)
    paths: list[Path] = args.paths or [Path(".")]
    progress = ProgressBar(sys.stderr, enabled=not args.quiet and show_progress(sys.stderr))
    stats: dict[str, int] = {}
    try:
        groups = _groups(args, paths)
        _read_histories(groups)
        if args.verbose:
            for config, _ in groups:
                _note(f"config: {config.source or 'defaults (no [tool.geolint] found)'}")
        results, config_of = _lint_groups(args, groups, progress.update, stats)
    except ConfigError as error:
        progress.close()
        _error(str(error))
        return EXIT_ERROR
    except api.DiscoveryError as error:
        progress.close()
        _error(str(error))
        return EXIT_ERROR
    progress.close()
    if not results:
        _warn_nothing_found(paths)
    unchecked = _report_errors(results, args.verbose)
    if not args.quiet:
        _note_history(groups)

    fixed_codes: dict[str, Counter[str]] = {}
    if args.fix or args.diff:
        results, fixed_codes, diffs = _fix(results, config_of, unsafe=args.unsafe_fixes, write=not args.diff)
        if args.diff:
            return _print_diffs(args, diffs, fixed_codes, unchecked)

    if args.add_noqa:
        added, files = _add_noqa(results)
        if not args.quiet:
            _note(f"Added {added} suppression comment{'s' * (added != 1)} to {files} file{'s' * (files != 1)}.")
        return EXIT_ERROR if unchecked else EXIT_OK

    if args.write_baseline:
        from geolint.baseline import write_baseline

        count = write_baseline([f for result in results for f in result.findings], args.write_baseline)
        if not args.quiet:
            _note(f"Recorded {count} finding{'s' * (count != 1)} in {args.write_baseline}.")
        return EXIT_ERROR if unchecked else EXIT_OK

    if args.verbose:
        _note(
            f"files: {stats.get('files', 0)}, from cache: {stats.get('cache_hits', 0)}, "
            f"linted: {stats.get('linted', 0)}, internal errors: {stats.get('errors', 0)}, "
            f"time: {time.perf_counter() - started:.2f}s"
        )
    return _report(args, [f for result in results for f in result.findings], fixed_codes, unchecked)


def _history_roots(groups: list[tuple[Config, list[SourceFile]]]) -> dict[str | None, Config]:
    from geolint.history import repository_of_folder

    roots: dict[str | None, Config] = {}
    for config, files in groups:
        if config.history and files:
            roots.setdefault(repository_of_folder(os.path.dirname(os.path.abspath(files[0].path))), config)
    return roots


def _read_histories(groups: list[tuple[Config, list[SourceFile]]]) -> None:
    """Read each repository's history once, before the workers start (they then find it cached)."""
    from geolint.history.mining import history_of

    for root, config in _history_roots(groups).items():
        if root is not None:
            history_of(root, config.history_limit)


def _note_history(groups: list[tuple[Config, list[SourceFile]]]) -> None:
    """Say when the history the run was asked to read is not there or is cut short (a shallow clone)."""
    from geolint.history.mining import history_of

    for root, config in _history_roots(groups).items():
        if root is None:
            _note("warning: --history: the files are not in a git repository; no fixes were read from history")
            continue
        found = history_of(root, config.history_limit)
        if found.shallow:
            _note(
                f"warning: --history: {root} is a shallow clone ({found.commits_read} commits read); fixes in older commits are "
                "not known (`git fetch --unshallow`, or `fetch-depth: 0` in CI)"
            )


# ---- which config for which file ----------------------------------------------------------------


def _groups(args: argparse.Namespace, paths: Sequence[Path]) -> list[tuple[Config, list[SourceFile]]]:
    """The files to lint, grouped by the config that applies to them (in first-seen order).

    Each path is walked with the config nearest to it; a file below a nearer `[tool.geolint]` of
    its own (a sub-project) goes with that config instead, and that config's excludes then apply
    to it too (unless it was named on the command line). One group is the usual answer.
    """
    from geolint.cache import DiscoveryCache, default_cache_dir
    from geolint.config import config_root
    from geolint.files import discover, is_excluded

    configs: dict[Path | None, Config] = {}
    config_of_folder: dict[str, Config] = {}  # by the folder as discovery spells it: one lookup per folder

    def config_at(folder: Path | str) -> Config:
        known = config_of_folder.get(str(folder))
        if known is not None:
            return known
        source = nearest_pyproject(Path(os.path.abspath(folder or os.curdir)))
        if source not in configs:
            configs[source] = _with_command_line(args, load_config(source) if source is not None else Config())
        config_of_folder[str(folder)] = configs[source]
        return configs[source]

    fixed_config = None
    if args.config is not None:
        if not args.config.is_file():
            raise ConfigError(args.config, None, "no such config file")
        fixed_config = _with_command_line(args, load_config(args.config))
    roots: dict[Config, list[Path]] = {}
    for path in paths:
        if not path.exists():
            raise api.DiscoveryError(f"{path}: no such file or directory")
        folder = Path(os.path.abspath(path))
        roots.setdefault(fixed_config or config_at(folder if path.is_dir() else folder.parent), []).append(path)
    named = {os.path.normpath(path) for path in paths if not path.is_dir()}
    grouped: dict[Config, list[SourceFile]] = {}
    seen: set[Path] = set()
    for config, root_paths in roots.items():
        listing = None if args.no_cache else DiscoveryCache(args.cache_dir or default_cache_dir(config_root(config)))
        for source_file in discover(root_paths, config, force_exclude=args.force_exclude, cache=listing):
            real = source_file.real_path()
            if real in seen:  # a file two paths name is linted once
                continue
            seen.add(real)
            own = fixed_config or config_at(os.path.dirname(source_file.path))
            if own.source != config.source and (args.force_exclude or os.path.normpath(source_file.path) not in named):
                if is_excluded(source_file.path, own):  # the sub-project's own excludes
                    continue
            grouped.setdefault(own, []).append(source_file)
    return list(grouped.items())


def _with_command_line(args: argparse.Namespace, config: Config) -> Config:
    """The config with the command line's selectors and excludes applied."""
    config = with_overrides(
        config,
        select=parse_selector_list(args.select) if args.select is not None else None,
        extend_select=parse_selector_list(args.extend_select) if args.extend_select else (),
        extend_ignore=parse_selector_list(args.ignore) if args.ignore else (),
    )
    if args.history:
        config = replace(config, history=True)
    if args.history_limit is not None:
        config = replace(config, history_limit=args.history_limit)
    if args.exclude:  # as ruff's --exclude: the command line's patterns instead of the config's
        config = replace(config, exclude=_patterns(args.exclude))
    if args.extend_exclude:
        config = replace(config, extend_exclude=config.extend_exclude + _patterns(args.extend_exclude))
    return config


def _patterns(values: Sequence[str]) -> tuple[str, ...]:
    """`--exclude a,b --exclude c` as the patterns a, b, c."""
    return tuple(part.strip() for value in values for part in value.split(",") if part.strip())


def _lint_groups(
    args: argparse.Namespace,
    groups: list[tuple[Config, list[SourceFile]]],
    progress: Callable[[int, int], None],
    stats: dict[str, int],
) -> tuple[list[api.FileResult], dict[str, Config]]:
    """Lint every group; the results sorted by path as one run gives them, and each file's config."""
    results: list[api.FileResult] = []
    config_of: dict[str, Config] = {}
    total = sum(len(sources) for _, sources in groups)
    done_before = 0
    for config, sources in groups:
        group_stats: dict[str, int] = {}

        def advanced(done: int, _: int, offset: int = done_before) -> None:
            progress(offset + done, total)

        for result in api.lint_paths(
            [],
            config,
            jobs=args.jobs,
            use_cache=not args.no_cache,
            cache_dir=args.cache_dir,
            progress=advanced,
            stats=group_stats,
            sources=sources,
        ):
            results.append(result)
            config_of[result.path] = config
        done_before += len(sources)
        for key, value in group_stats.items():
            stats[key] = stats.get(key, 0) + value
    if len(groups) > 1:
        results.sort(key=lambda result: result.path)
    return results, config_of


# ---- stdin --------------------------------------------------------------------------------------


def _check_stdin(args: argparse.Namespace, started: float) -> int:
    """`geolint check - --stdin-filename PATH`: lint the text on stdin as if it were PATH (for editors
    without a language server). With `--fix` the fixed text goes to stdout and the report to stderr."""
    from geolint.engine import decode_source, encode_source, lint_bytes
    from geolint.notebook import NotebookError, is_notebook, read_notebook, remember_notebook, unreadable_notebook, write_back
    from geolint.output.source import remember_text

    data = sys.stdin.buffer.read()
    name = args.stdin_filename or "-"
    display = os.path.normpath(name) if args.stdin_filename else name
    try:
        if args.config is not None:
            if not args.config.is_file():
                raise ConfigError(args.config, None, "no such config file")
            config = _with_command_line(args, load_config(args.config))
        else:
            folder = Path(os.path.abspath(name)).parent if args.stdin_filename else Path.cwd()
            source = nearest_pyproject(folder)
            config = _with_command_line(args, load_config(source) if source is not None else Config())
    except ConfigError as error:
        _error(str(error))
        return EXIT_ERROR
    if args.verbose:
        _note(f"config: {config.source or 'defaults (no [tool.geolint] found)'}")
    if args.force_exclude and args.stdin_filename and _is_excluded(Path(name), config):
        if args.fix:
            sys.stdout.buffer.write(data)  # an editor replaces its buffer with what comes back
        return EXIT_OK
    notebook = None
    if is_notebook(display):
        try:
            notebook = read_notebook(data)
        except NotebookError as error:
            if args.fix:
                sys.stdout.buffer.write(data)
            return _report(args, unreadable_notebook(display, config, error), {}, 0, stream=sys.stderr if args.fix else None)
        remember_notebook(display, notebook)
        python = notebook.python.encode("utf-8")
    else:
        python = data
    try:
        text, encoding = decode_source(python)
    except (SyntaxError, UnicodeDecodeError, LookupError):
        text, encoding = None, "utf-8"
    try:
        findings = lint_bytes(python, display, config)
    except Exception as error:  # an internal error: reported, as for a file
        _error(f"internal error while checking {display}; please report it:\n  {type(error).__name__}: {error}")
        return EXIT_ERROR
    if text is not None:
        remember_text(display, text)
    fixed_codes: dict[str, Counter[str]] = {}
    if (args.fix or args.diff) and text is not None:
        from geolint.fixes import fix_source

        outcome = fix_source(text, display, config, unsafe=args.unsafe_fixes)
        try:
            fixed = write_back(data, outcome.source) if notebook is not None else encode_source(outcome.source, encoding)
        except NotebookError as error:
            _error(f"cannot fix {display}: {error}")
            fixed, outcome = data, replace(outcome, source=text, fixed=0, remaining=tuple(findings), fixed_codes=())
        if args.diff:
            diffs = [_unified_diff(display, data, fixed)] if outcome.changed else []
            return _print_diffs(args, diffs, {display: Counter(outcome.fixed_codes)} if outcome.changed else {}, 0)
        sys.stdout.buffer.write(fixed)
        sys.stdout.flush()
        if outcome.changed:
            fixed_codes[display] = Counter(outcome.fixed_codes)
            remember_text(display, outcome.source)
            if notebook is not None:
                remember_notebook(display, read_notebook(fixed))
        findings = list(outcome.remaining)
        return _report(args, findings, fixed_codes, 0, stream=sys.stderr)  # stdout holds the fixed text
    elif args.fix:
        sys.stdout.buffer.write(data)
    return _report(args, findings, fixed_codes, 0)


def _is_excluded(path: Path, config: Config) -> bool:
    from geolint.files import is_excluded

    return is_excluded(path, config)


# ---- reporting ----------------------------------------------------------------------------------


def _report_errors(results: Sequence[api.FileResult], verbose: bool) -> int:
    """Print the files that could not be checked; how many there are (broken links only warn)."""
    unchecked = 0
    for result in results:
        if result.broken_link:  # as ruff users expect: a warning, and the run goes on without it
            _warning(f"skipped {result.path}: {result.error}")
        elif result.unreadable:
            unchecked += 1
            _error(f"cannot read {result.path}: {result.error}")
        elif result.error is not None:
            unchecked += 1
            detail = result.error.rstrip() if verbose else result.error.rstrip().splitlines()[-1]
            hint = "" if verbose else " (--verbose shows the traceback)"
            _error(f"internal error while checking {result.path}{hint}; please report it:\n  {detail}")
    return unchecked


def _print_diffs(args: argparse.Namespace, diffs: list[bytes], fixed_codes: dict[str, Counter[str]], unchecked: int) -> int:
    fixed_total = sum(sum(counts.values()) for counts in fixed_codes.values())
    sys.stdout.flush()
    sys.stdout.buffer.write(b"".join(diffs))  # each diff in its file's own encoding, as patch reads it
    sys.stdout.buffer.flush()
    if not args.quiet:
        _note(f"Would fix {fixed_total} finding{'s' * (fixed_total != 1)}." if fixed_total else "No fixes available.")
    return EXIT_ERROR if unchecked else (EXIT_FINDINGS if diffs else EXIT_OK)


def _report(
    args: argparse.Namespace,
    findings: list[Finding],
    fixed_codes: dict[str, Counter[str]],
    unchecked: int,
    stream=None,
) -> int:
    """Print the findings (less a baseline's) and the summary; the exit code."""
    known = 0
    if args.baseline:
        from geolint.baseline import BaselineError, new_findings

        try:
            remaining = new_findings(findings, args.baseline)
        except BaselineError as error:
            _error(str(error))
            return EXIT_ERROR
        known, findings = len(findings) - len(remaining), remaining

    out = stream or sys.stdout
    to_file = args.output is not None
    human = args.format in HUMAN_FORMATS
    color = human and not to_file and use_color(out)
    if args.statistics:
        text = _statistics(findings, args.format)
    else:
        text = render(findings, args.format, color=color, show_fixes=args.show_fixes, unsafe_fixes=args.unsafe_fixes)
        if args.show_fixes and fixed_codes and human:
            text = _fixed_list(fixed_codes, bool(findings)) + text
    if to_file:
        try:
            args.output.write_text(text, encoding="utf-8")
        except OSError as error:
            _error(f"{args.output}: cannot write output: {error.strerror or error}")
            return EXIT_ERROR
    else:
        out.write(text)
        out.flush()

    fixed_total = sum(sum(counts.values()) for counts in fixed_codes.values())
    if not args.quiet:
        summary = _summary(findings, fixed_total, known, unchecked)
        if human and not to_file and not args.statistics:
            out.write(summary + "\n")
            out.flush()
        else:
            _note(summary)

    if unchecked:
        return EXIT_ERROR
    if any(Severity(f.severity) in FAILING for f in findings) and not args.exit_zero:
        return EXIT_FINDINGS
    if fixed_total and args.exit_non_zero_on_fix:
        return EXIT_FINDINGS
    return EXIT_OK


# ---- fixes --------------------------------------------------------------------------------------


def _fix(
    results: list[api.FileResult], config_of: dict[str, Config], *, unsafe: bool, write: bool
) -> tuple[list[api.FileResult], dict[str, Counter[str]], list[bytes]]:
    """Fix every file that has an applicable fix; returns new results, the codes fixed in each file, and diffs."""
    from geolint.engine import encode_source
    from geolint.fixes import fix_source, fixable
    from geolint.notebook import is_notebook, write_back

    updated: list[api.FileResult] = []
    fixed_codes: dict[str, Counter[str]] = {}
    diffs: list[bytes] = []
    for result in results:
        if result.error or result.location is None or not any(fixable(f, unsafe=unsafe) for f in result.findings):
            updated.append(result)
            continue
        try:
            data = result.location.read_bytes()
            source, encoding = _python_of(result.location, data)
            # the findings this run just gave for these very bytes: the first fix pass needs no new lint
            # (a notebook's are placed in its cells, not in the code the fix reads)
            known = None if is_notebook(result.location) else result.findings
            outcome = fix_source(source, result.path, config_of[result.path], unsafe=unsafe, findings=known)
            if outcome.changed:
                fixed = write_back(data, outcome.source) if is_notebook(result.location) else encode_source(outcome.source, encoding)
                if write:
                    result.location.write_bytes(fixed)
                    _forget_text(result.path)
                else:
                    diffs.append(_unified_diff(result.path, data, fixed))
                fixed_codes[result.path] = Counter(outcome.fixed_codes)
                updated.append(api.FileResult(result.path, outcome.remaining, location=result.location))
            else:
                updated.append(result)
        except Exception as error:  # one file's failure to fix must not lose the others' results
            _error(f"cannot fix {result.path}: {error}")
            updated.append(result)
    return updated, fixed_codes, diffs


def _unified_diff(path: str, before: bytes, after: bytes) -> bytes:
    """A unified diff of a file's bytes before and after `--fix`, as `patch` and `git apply` read one.

    Lines end at \n only (a \r, a form feed stay inside their line, so CRLF and CR-only files
    diff exactly); the bytes keep the file's own encoding and BOM; a last line without \n is
    followed by the "\\ No newline at end of file" marker.
    """
    name = os.fsencode(path)
    absolute = os.path.isabs(path)
    lines = difflib.diff_bytes(
        difflib.unified_diff,
        _byte_lines(before),
        _byte_lines(after),
        fromfile=name if absolute else b"a/" + name,
        tofile=name if absolute else b"b/" + name,
    )
    return b"".join(line if line.endswith(b"\n") else line + b"\n\\ No newline at end of file\n" for line in lines)


def _byte_lines(data: bytes) -> list[bytes]:
    """The lines of `data`, each with its \n (the last one may have none)."""
    lines = data.split(b"\n")
    return [line + b"\n" for line in lines[:-1]] + ([lines[-1]] if lines[-1] else [])


def _python_of(location: Path, data: bytes) -> tuple[str, str]:
    """The Python text of a file's bytes and its encoding (a notebook's: its code cells, UTF-8)."""
    from geolint.engine import decode_source
    from geolint.notebook import is_notebook, read_notebook

    return (read_notebook(data).python, "utf-8") if is_notebook(location) else decode_source(data)


def _forget_text(path: str) -> None:
    """A file was rewritten: the output must show its new lines (and a notebook's new cells)."""
    from geolint.engine import read_source_lines
    from geolint.notebook import forget_notebooks
    from geolint.output.source import forget_text

    read_source_lines.cache_clear()
    forget_notebooks()
    forget_text(path)


def _add_noqa(results: list[api.FileResult]) -> tuple[int, int]:
    from geolint.engine import SYNTAX_ERROR, encode_source
    from geolint.fixes import parses
    from geolint.notebook import NotebookError, is_notebook, write_back
    from geolint.suppression import UNUSED_SUPPRESSION, add_suppressions

    added = files = 0
    for result in results:
        targets = [f for f in result.findings if f.code not in (SYNTAX_ERROR, UNUSED_SUPPRESSION)]
        if not targets or result.location is None:
            continue
        data = result.location.read_bytes()
        source, encoding = _python_of(result.location, data)
        new_source = add_suppressions(source, targets)
        if new_source == source or not parses(new_source):
            _error(f"{result.path}: could not add suppression comments without breaking the file; left unchanged")
            continue
        try:
            written = write_back(data, new_source) if is_notebook(result.location) else encode_source(new_source, encoding)
        except NotebookError as error:
            _error(f"{result.path}: {error}")
            continue
        result.location.write_bytes(written)
        added += len(targets)
        files += 1
    return added, files


def _statistics(findings: Sequence[Finding], format_name: str) -> str:
    counts = Counter(f.code for f in findings)
    names = {f.code: f.name for f in findings}
    fixable = {f.code for f in findings if f.fix is not None}
    rows = sorted(counts.items(), key=lambda item: (-item[1], item[0]))
    if format_name == "json":
        import json

        table = [{"code": c, "name": names[c], "count": n, "fixable": c in fixable} for c, n in rows]
        return json.dumps(table, indent=2) + "\n"
    width = max((len(str(n)) for _, n in rows), default=1)
    return "".join(f"{n:>{width}}\t{c}\t{'[*] ' if c in fixable else ''}{names[c]}\n" for c, n in rows)


def _fixed_list(fixed_codes: dict[str, Counter[str]], more_follows: bool) -> str:
    """`--fix --show-fixes`: what was fixed, file by file (`    2 x GEO101 (direction-translated)`)."""
    from geolint.rules import rule_by_code

    total = sum(sum(counts.values()) for counts in fixed_codes.values())
    lines = [f"Fixed {total} finding{'s' * (total != 1)}:"]
    for path in sorted(fixed_codes):
        lines.append(f"- {path}:")
        for code, count in sorted(fixed_codes[path].items()):
            rule = rule_by_code(code)
            lines.append(f"    {count} x {code}{f' ({rule.name})' if rule is not None else ''}")
    return "\n".join(lines) + "\n" + ("\n" if more_follows else "")


def _summary(findings: Sequence[Finding], fixed: int, known: int, unchecked: int = 0) -> str:
    parts = []
    if fixed:
        parts.append(f"Fixed {fixed} finding{'s' * (fixed != 1)}.")
    if findings:
        safe = sum(1 for f in findings if f.fix is not None and f.fix.applicability == "safe")
        unsafe = sum(1 for f in findings if f.fix is not None and f.fix.applicability != "safe")
        line = f"Found {len(findings)} finding{'s' * (len(findings) != 1)}"
        by_severity = Counter(Severity(f.severity) for f in findings)
        hints = []
        if set(by_severity) != {Severity.ERROR}:  # the mix, when it is not only errors
            hints.append(", ".join(_severity_count(level, by_severity[level]) for level in Severity if by_severity[level]))
        fixes = [f"{safe} fixable with --fix"] if safe else []
        if unsafe:
            fixes.append(f"{unsafe} more with --fix --unsafe-fixes")
        if fixes:
            hints.append(", ".join(fixes))
        parts.append(line + (f" ({'; '.join(hints)})" if hints else "") + ".")
        if not any(level in FAILING for level in by_severity):
            parts.append("Info and hint findings do not fail the run.")
    elif not unchecked:  # only when every file was checked
        parts.append("All checks passed.")
    if unchecked:
        parts.append(f"{unchecked} file{'s' * (unchecked != 1)} could not be checked (errors above).")
    if known:
        parts.append(f"({known} known finding{'s' * (known != 1)} hidden by the baseline.)")
    return " ".join(parts)


def _severity_count(level: Severity, count: int) -> str:
    plural = "s" if count != 1 and level in FAILING else ""  # "2 errors", "2 warnings", but "2 info"
    return f"{count} {level.value}{plural}"


def _warn_nothing_found(paths: Sequence[Path]) -> None:
    shown = ", ".join(str(path) for path in paths)
    sys.stderr.write(
        f"geolint: warning: no Python files found under {shown} (.venv, build, dist and the config's "
        "`exclude` are skipped, and so is what .gitignore lists; name such a folder to lint it)\n"
    )
    sys.stderr.flush()


def _error(message: str) -> None:
    sys.stderr.write(f"geolint: error: {message}\n")


def _warning(message: str) -> None:
    sys.stderr.write(f"geolint: warning: {message}\n")


def _note(message: str) -> None:
    sys.stderr.write(message + "\n")
