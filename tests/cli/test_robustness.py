"""Bad input never stops a run: syntax errors, odd encodings, new syntax, internal errors in a rule."""

from __future__ import annotations

import json


def by_path(result) -> dict[str, list[dict]]:
    grouped: dict[str, list[dict]] = {}
    for finding in json.loads(result.stdout):
        grouped.setdefault(finding["path"], []).append(finding)
    return grouped


def test_a_syntax_error_is_one_geo000_and_the_run_goes_on(cli):
    cli.write("a_broken.py", "def transform(R, normals:\n    return normals @ R.T\nx = bad_thing\n")
    cli.write("b_fine.py", "x = bad_thing\n")
    cli.write("c_python2.py", 'print "hello"\n')
    result = cli("check", "--format", "json")
    assert result.returncode == 1
    found = by_path(result)
    [broken] = found["a_broken.py"]
    assert (broken["code"], broken["name"], broken["line"]) == ("GEO000", "syntax-error", 1)
    assert "never closed" in broken["message"] or "syntax" in broken["message"]
    assert [f["code"] for f in found["c_python2.py"]] == ["GEO000"]
    assert [f["code"] for f in found["b_fine.py"]] == ["GEO190"]


def test_encodings(cli):
    cli.write("latin.py", "# -*- coding: latin-1 -*-\nname = 'señal'\nx = bad_thing\n", encoding="latin-1")
    (cli.project / "bom.py").write_bytes(b"\xef\xbb\xbfx = bad_thing\n")
    (cli.project / "undecodable.py").write_bytes(b"ok = 1\nname = '\xff\xfe'\n")
    (cli.project / "unknown_cookie.py").write_bytes(b"# -*- coding: klingon -*-\nx = 1\n")
    (cli.project / "nul.py").write_bytes(b"x = 1\x00\n")
    (cli.project / "empty.py").write_bytes(b"")
    result = cli("check", "--format", "json")
    assert result.returncode == 1, result.stderr
    found = by_path(result)
    assert [f["code"] for f in found["latin.py"]] == ["GEO190"]
    assert found["latin.py"][0]["line"] == 3
    assert [(f["code"], f["line"], f["column"]) for f in found["bom.py"]] == [("GEO190", 1, 5)]
    [undecodable] = found["undecodable.py"]
    assert (undecodable["code"], undecodable["line"], undecodable["column"]) == ("GEO000", 2, 9)
    assert "0xff" in undecodable["message"] and "coding" in undecodable["message"]
    assert "klingon" in found["unknown_cookie.py"][0]["message"]
    assert [f["code"] for f in found["nul.py"]] == ["GEO000"]
    assert "empty.py" not in found


def test_syntax_newer_than_this_python_is_read_and_fixed(cli):
    # PEP 695 (Python 3.12) syntax: read under an older Python too, and its fix built by libcst
    path = cli.write("modern.py", "type Vec = list[float]\nx = bad_thing\n")
    result = cli("check", "--format", "json")
    assert [(f["code"], f["fix"] is not None) for f in json.loads(result.stdout)] == [("GEO190", True)]
    assert cli("check", "--fix").returncode == 0 and path.read_text() == "type Vec = list[float]\nx = good_thing\n"


def test_crlf_form_feed_and_tabs_keep_positions_right(cli):
    (cli.project / "odd.py").write_bytes(b"a = 1\r\n\x0c\r\nif a:\r\n\tb = bad_thing\r\n")
    [finding] = json.loads(cli("check", "--format", "json").stdout)
    assert (finding["line"], finding["column"], finding["end_column"]) == (4, 6, 15)


def test_an_internal_error_is_reported_with_its_path_and_exits_2(cli):
    cli.write("a.py", "x = bad_thing\n")
    cli.write("b_crash.py", "crash_here = 1\n")
    cli.write("c.py", "y = bad_thing\n")
    result = cli("check", "--format", "json")
    assert result.returncode == 2
    assert "b_crash.py" in result.stderr and "crashed on purpose" in result.stderr
    assert sorted(by_path(result)) == ["a.py", "c.py"]  # the other files were still checked
    verbose = cli("check", "--verbose")
    assert "Traceback" in verbose.stderr
    # an error is never cached: the next run tries the file again
    assert "linted: 1" in verbose.stderr


def test_a_large_file(cli):
    # Big enough to catch anything quadratic in the file's length, small enough to stay quick.
    lines = [f"value_{i} = compute({i}) + offset  # line {i}" for i in range(1500)]
    lines[1400] = "value = bad_thing"
    cli.write("large.py", "\n".join(lines) + "\n")
    [finding] = json.loads(cli("check", "--format", "json").stdout)
    assert finding["line"] == 1401
