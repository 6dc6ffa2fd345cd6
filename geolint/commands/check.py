"""`geolint check [PATH ...]`: lint files and folders, print findings, optionally fix them.

Exit codes: 0 nothing to report, 1 findings (or, with `--exit-non-zero-on-fix`, files fixed),
2 a usage, config or internal error. Findings go to stdout (or `--output FILE`) in the chosen
format. The text format's summary follows the findings on stdout, so a piped CI log reads top to
bottom; with a machine format or `--output` it goes to stderr, so stdout stays machine-readable.
Progress, warnings and errors go to stderr.
"""

from __future__ import annotations

import argparse
import difflib
import os
import sys
import time
from collections import Counter
from pathlib import Path
from typing import Sequence

from geolint import api
from geolint.cli import EXIT_ERROR, EXIT_FINDINGS, EXIT_OK
from geolint.config import ConfigError, load_config, parse_selector_list, with_overrides
from geolint.lint_types import Config, Finding
from geolint.output import FORMATS, render
from geolint.terminal import ProgressBar, show_progress, use_color


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("paths", nargs="*", type=Path, metavar="PATH", help="files or folders to lint (default: .)")
    parser.add_argument("--config", type=Path, metavar="FILE", help="use this pyproject.toml instead of the nearest one")
    parser.add_argument("--select", metavar="CODES", help="comma-separated codes or prefixes to enable (replaces the config's)")
    parser.add_argument("--extend-select", metavar="CODES", help="comma-separated codes or prefixes to enable as well (adds to the config's)")
    parser.add_argument("--ignore", metavar="CODES", help="comma-separated codes or prefixes to disable (adds to the config's)")
    parser.add_argument("--format", choices=FORMATS, default="text", help="output format (default: text)")
    parser.add_argument("--output", type=Path, metavar="FILE", help="write findings to FILE instead of stdout")
    parser.add_argument("--statistics", action="store_true", help="print how often each code occurs instead of the findings")
    parser.add_argument("--exit-zero", action="store_true", help="exit 0 even when there are findings")
    parser.add_argument("--jobs", "-j", type=_positive_int, metavar="N", help="worker processes (default: all cores)")
    parser.add_argument("--no-cache", action="store_true", help="neither read nor write the findings cache")
    parser.add_argument("--cache-dir", type=Path, metavar="DIR", help="where to keep the cache (default: <root>/.geolint_cache)")
    parser.add_argument("--force-exclude", action="store_true", help="apply excludes to files named on the command line too")
    fixing = parser.add_argument_group("fixes")
    fixing.add_argument("--fix", action="store_true", help="apply safe fixes in place")
    fixing.add_argument("--unsafe-fixes", action="store_true", help="with --fix or --diff, apply unsafe fixes too")
    fixing.add_argument("--diff", action="store_true", help="print the fixes as unified diffs; change no file")
    fixing.add_argument("--exit-non-zero-on-fix", action="store_true", help="exit 1 when --fix changed a file")
    adoption = parser.add_argument_group("adopting geolint on existing code")
    adoption.add_argument("--write-baseline", type=Path, metavar="FILE", help="record the current findings in FILE and exit 0")
    adoption.add_argument("--baseline", type=Path, metavar="FILE", help="report only findings that FILE does not record")
    adoption.add_argument("--add-noqa", action="store_true", help="add a `# geolint: ignore[...]` comment for every finding")
    talk = parser.add_mutually_exclusive_group()
    talk.add_argument("--quiet", "-q", action="store_true", help="print findings only (no summary, no progress)")
    talk.add_argument("--verbose", "-v", action="store_true", help="also print config, file and cache counts, timing")


def _positive_int(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError("must be at least 1")
    return value


def run(args: argparse.Namespace) -> int:
    started = time.perf_counter()
    paths: list[Path] = args.paths or [Path(".")]
    try:
        config = _config(args, paths)
    except ConfigError as error:
        _error(str(error))
        return EXIT_ERROR
    if args.verbose:
        _note(f"config: {config.source or 'defaults (no [tool.geolint] found)'}")

    progress = ProgressBar(sys.stderr, enabled=not args.quiet and show_progress(sys.stderr))
    stats: dict[str, int] = {}
    try:
        results = list(
            api.lint_paths(
                paths,
                config,
                jobs=args.jobs,
                use_cache=not args.no_cache,
                force_exclude=args.force_exclude,
                cache_dir=args.cache_dir,
                progress=progress.update,
                stats=stats,
            )
        )
    except api.DiscoveryError as error:
        progress.close()
        _error(str(error))
        return EXIT_ERROR
    progress.close()
    if not results:
        _warn_nothing_found(paths)

    unchecked = 0
    for result in results:
        if result.broken_link:  # as ruff users expect: a warning, and the run goes on without it
            _warning(f"skipped {result.path}: {result.error}")
        elif result.unreadable:
            unchecked += 1
            _error(f"cannot read {result.path}: {result.error}")
        elif result.error is not None:
            unchecked += 1
            detail = result.error.rstrip() if args.verbose else result.error.rstrip().splitlines()[-1]
            hint = "" if args.verbose else " (--verbose shows the traceback)"
            _error(f"internal error while checking {result.path}{hint}; please report it:\n  {detail}")

    fixed_total = 0
    if args.fix or args.diff:
        results, fixed_total, diffs = _fix(results, config, unsafe=args.unsafe_fixes, write=not args.diff)
        if args.diff:
            sys.stdout.flush()
            sys.stdout.buffer.write(b"".join(diffs))  # each diff in its file's own encoding, as patch reads it
            sys.stdout.buffer.flush()
            if not args.quiet:
                _note(f"Would fix {fixed_total} finding{'s' * (fixed_total != 1)}." if fixed_total else "No fixes available.")
            return EXIT_ERROR if unchecked else (EXIT_FINDINGS if diffs else EXIT_OK)

    findings = [finding for result in results for finding in result.findings]

    if args.add_noqa:
        added, files = _add_noqa(results)
        if not args.quiet:
            _note(f"Added {added} suppression comment{'s' * (added != 1)} to {files} file{'s' * (files != 1)}.")
        return EXIT_ERROR if unchecked else EXIT_OK

    if args.write_baseline:
        from geolint.baseline import write_baseline

        count = write_baseline(findings, args.write_baseline)
        if not args.quiet:
            _note(f"Recorded {count} finding{'s' * (count != 1)} in {args.write_baseline}.")
        return EXIT_ERROR if unchecked else EXIT_OK

    known = 0
    if args.baseline:
        from geolint.baseline import BaselineError, new_findings

        try:
            remaining = new_findings(findings, args.baseline)
        except BaselineError as error:
            _error(str(error))
            return EXIT_ERROR
        known, findings = len(findings) - len(remaining), remaining

    to_file = args.output is not None
    color = args.format == "text" and not to_file and use_color(sys.stdout)
    text = _statistics(findings, args.format) if args.statistics else render(findings, args.format, color=color)
    if to_file:
        try:
            args.output.write_text(text, encoding="utf-8")
        except OSError as error:
            _error(f"{args.output}: cannot write output: {error.strerror or error}")
            return EXIT_ERROR
    else:
        sys.stdout.write(text)
        sys.stdout.flush()

    if args.verbose:
        _note(
            f"files: {stats.get('files', 0)}, from cache: {stats.get('cache_hits', 0)}, "
            f"linted: {stats.get('linted', 0)}, internal errors: {stats.get('errors', 0)}, "
            f"time: {time.perf_counter() - started:.2f}s"
        )
    if not args.quiet:
        summary = _summary(findings, fixed_total, known, unchecked)
        if args.format == "text" and not to_file and not args.statistics:
            sys.stdout.write(summary + "\n")
            sys.stdout.flush()
        else:
            _note(summary)

    if unchecked:
        return EXIT_ERROR
    if findings and not args.exit_zero:
        return EXIT_FINDINGS
    if fixed_total and args.exit_non_zero_on_fix:
        return EXIT_FINDINGS
    return EXIT_OK


def _config(args: argparse.Namespace, paths: Sequence[Path]) -> Config:
    if args.config is not None:
        if not args.config.is_file():
            raise ConfigError(args.config, None, "no such config file")
        config = load_config(args.config)
    else:
        config = api.find_config(_common_folder(paths))
    return with_overrides(
        config,
        select=parse_selector_list(args.select) if args.select is not None else None,
        extend_select=parse_selector_list(args.extend_select) if args.extend_select else (),
        extend_ignore=parse_selector_list(args.ignore) if args.ignore else (),
    )


def _common_folder(paths: Sequence[Path]) -> Path:
    """Where to start looking for pyproject.toml: the deepest folder containing every path."""
    existing = [os.path.abspath(p) for p in paths if p.exists()]
    if not existing:
        return Path.cwd()
    common = Path(os.path.commonpath(existing))
    return common if common.is_dir() else common.parent


def _fix(
    results: list[api.FileResult], config: Config, *, unsafe: bool, write: bool
) -> tuple[list[api.FileResult], int, list[bytes]]:
    """Fix every file that has an applicable fix; returns new results, the count fixed, and diffs."""
    from geolint.engine import decode_source, encode_source
    from geolint.fixes import fix_source, fixable

    updated: list[api.FileResult] = []
    fixed_total = 0
    diffs: list[bytes] = []
    for result in results:
        if result.error or result.location is None or not any(fixable(f, unsafe=unsafe) for f in result.findings):
            updated.append(result)
            continue
        try:
            data = result.location.read_bytes()
            source, encoding = decode_source(data)
            outcome = fix_source(source, result.path, config, unsafe=unsafe)
            if outcome.changed:
                fixed = encode_source(outcome.source, encoding)
                if write:
                    result.location.write_bytes(fixed)
                else:
                    diffs.append(_unified_diff(result.path, data, fixed))
                fixed_total += outcome.fixed
                updated.append(api.FileResult(result.path, outcome.remaining, location=result.location))
            else:
                updated.append(result)
        except Exception as error:  # one file's failure to fix must not lose the others' results
            _error(f"cannot fix {result.path}: {error}")
            updated.append(result)
    return updated, fixed_total, diffs


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


def _add_noqa(results: list[api.FileResult]) -> tuple[int, int]:
    from geolint.engine import SYNTAX_ERROR, decode_source, encode_source
    from geolint.fixes import parses
    from geolint.suppression import UNUSED_SUPPRESSION, add_suppressions

    added = files = 0
    for result in results:
        targets = [f for f in result.findings if f.code not in (SYNTAX_ERROR, UNUSED_SUPPRESSION)]
        if not targets or result.location is None:
            continue
        data = result.location.read_bytes()
        source, encoding = decode_source(data)
        new_source = add_suppressions(source, targets)
        if new_source == source or not parses(new_source):
            _error(f"{result.path}: could not add suppression comments without breaking the file; left unchanged")
            continue
        result.location.write_bytes(encode_source(new_source, encoding))
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


def _summary(findings: Sequence[Finding], fixed: int, known: int, unchecked: int = 0) -> str:
    parts = []
    if fixed:
        parts.append(f"Fixed {fixed} finding{'s' * (fixed != 1)}.")
    if findings:
        safe = sum(1 for f in findings if f.fix is not None and f.fix.applicability == "safe")
        unsafe = sum(1 for f in findings if f.fix is not None and f.fix.applicability != "safe")
        line = f"Found {len(findings)} finding{'s' * (len(findings) != 1)}"
        hints = [f"{safe} fixable with --fix"] if safe else []
        if unsafe:
            hints.append(f"{unsafe} more with --fix --unsafe-fixes")
        parts.append(line + (f" ({', '.join(hints)})" if hints else "") + ".")
    elif not unchecked:  # only when every file was checked
        parts.append("All checks passed.")
    if unchecked:
        parts.append(f"{unchecked} file{'s' * (unchecked != 1)} could not be checked (errors above).")
    if known:
        parts.append(f"({known} known finding{'s' * (known != 1)} hidden by the baseline.)")
    return " ".join(parts)


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
