"""The findings cache and parallel runs, through the real CLI (hits counted via --verbose, not timing)."""

from __future__ import annotations

import json
import os
import re
import time

from geolint.cache import content_hash


def counts(stderr: str) -> tuple[int, int]:
    match = re.search(r"files: (\d+), from cache: (\d+), linted: (\d+)", stderr)
    assert match, stderr
    return int(match.group(2)), int(match.group(3))


def test_second_run_is_served_from_the_cache_until_a_file_or_the_config_changes(cli):
    for index in range(3):
        cli.write(f"m{index}.py", f"x{index} = bad_thing\n")
    first = cli("check", "--verbose", "--format", "json")
    assert counts(first.stderr) == (0, 3)
    second = cli("check", "--verbose", "--format", "json")
    assert counts(second.stderr) == (3, 0)
    assert second.stdout == first.stdout and second.returncode == first.returncode == 1
    assert (cli.cache_dir / ".gitignore").read_text().strip().endswith("*")

    cli.write("m1.py", "x1 = risky_thing\n")
    third = cli("check", "--verbose", "--format", "json")
    assert counts(third.stderr) == (2, 1)
    assert [f["code"] for f in json.loads(third.stdout)] == ["GEO190", "GEO191", "GEO190"]

    # another selection is another cache key: nothing stale leaks through
    selected = cli("check", "--verbose", "--format", "json", "--select", "GEO191")
    assert counts(selected.stderr) == (0, 3)
    assert [f["code"] for f in json.loads(selected.stdout)] == ["GEO191"]
    cli.write("pyproject.toml", '[tool.geolint]\nignore = ["GEO190"]\n')
    configured = cli("check", "--verbose", "--format", "json")
    assert counts(configured.stderr) == (0, 3)


def test_no_cache_neither_reads_nor_writes(cli):
    cli.write("m.py", "x = bad_thing\n")
    first = cli("check", "--verbose", "--no-cache")
    assert counts(first.stderr) == (0, 1)
    assert not cli.cache_dir.exists()
    cli("check")
    assert counts(cli("check", "--verbose", "--no-cache").stderr) == (0, 1)


def test_default_cache_lives_in_the_project_root_and_ignores_itself(cli, tmp_path):
    cli.write("pyproject.toml", "[tool.geolint]\n")
    cli.write("src/m.py", "x = bad_thing\n")
    env = {"GEOLINT_CACHE_DIR": ""}
    cli("check", "src", env=env)
    cache = cli.project / ".geolint_cache"
    assert any(cache.glob("findings-*.json")) and (cache / ".gitignore").is_file()
    assert counts(cli("check", "src", "--verbose", env=env).stderr) == (1, 0)


def test_jobs_2_gives_the_same_output_as_jobs_1(cli):
    for index in range(24):
        body = "\n".join(f"v{j} = {'bad_thing' if (index + j) % 3 == 0 else 'risky_thing'}" for j in range(index % 5 + 1))
        cli.write(f"pkg/sub{index % 4}/mod{index}.py", body + "\n")
    cli.write("pkg/broken.py", "def f(:\n")
    serial = cli("check", "--no-cache", "--jobs", "1", "--format", "json")
    parallel = cli("check", "--no-cache", "--jobs", "2", "--format", "json")
    assert serial.returncode == parallel.returncode == 1
    assert parallel.stdout == serial.stdout
    paths = [f["path"] for f in json.loads(serial.stdout)]
    assert paths == sorted(paths) and len(set(paths)) == 25


def _age_folders(root, seconds: int = 3600) -> None:
    """Date every folder under `root` (itself included) back, as a tree left alone for a while is."""
    stamp = time.time() - seconds
    for folder, _, _ in os.walk(root):
        os.utime(folder, (stamp, stamp))


def _write_importer(cli_real, path: str, module: str) -> None:
    """A module that hands normals to `module.apply_pose` (GEO101 once that helper translates)."""
    cli_real.write(
        path,
        f"from {module} import apply_pose\n\n\ndef move(pose, mesh):\n"
        "    normals = mesh.vertex_normals\n    return apply_pose(pose, normals)\n",
    )


def _slam_project(cli_real) -> None:
    cli_real.write("setup.py", "")
    cli_real.write("slam/__init__.py", "")
    _write_importer(cli_real, "slam/mapping.py", "slam.geometry")


_GEOMETRY = (
    "def apply_pose(pose, points):\n    rotation, translation = pose[:3, :3], pose[:3, 3]\n"
    "    return points @ rotation.T + translation\n"
)


def test_an_imported_module_created_after_a_run_relints_its_importer(cli_real):
    """The first run finds no `slam/geometry.py` (its folder listing says so); once the module exists,
    the importer's digest changes and the next run reads the helper's summary."""
    _slam_project(cli_real)
    first = cli_real("check", "--verbose", "--format", "json")
    assert counts(first.stderr) == (0, 3) and json.loads(first.stdout) == []
    cli_real.write("slam/geometry.py", _GEOMETRY)
    second = cli_real("check", "--verbose", "--format", "json")
    assert counts(second.stderr) == (2, 2)  # setup.py and __init__.py unchanged; mapping.py and the new module linted
    assert [(f["path"], f["code"]) for f in json.loads(second.stdout)] == [("slam/mapping.py", "GEO101")]


def test_resolved_imports_are_reused_while_the_folders_they_were_resolved_in_keep_their_mtime(cli_real):
    """The second run takes mapping.py's imports from the first: proven by hiding a new module behind the
    folder's old mtime (nothing a real edit does), which the reused resolution then does not see."""
    _slam_project(cli_real)
    _age_folders(cli_real.project)
    first = cli_real("check", "--verbose", "--format", "json")
    assert counts(first.stderr) == (0, 3) and json.loads(first.stdout) == []
    assert len(list(cli_real.cache_dir.glob("imports-*.json"))) == 1

    slam = cli_real.project / "slam"
    before = os.stat(slam)
    cli_real.write("slam/geometry.py", _GEOMETRY)
    os.utime(slam, ns=(before.st_atime_ns, before.st_mtime_ns))
    for listing in cli_real.cache_dir.glob("discovery-*.json"):
        listing.unlink()  # the reused listing would hide the module too: this test is about the imports
    hidden = cli_real("check", "--verbose", "--format", "json")
    assert counts(hidden.stderr) == (3, 1) and json.loads(hidden.stdout) == []  # only the new module linted


def test_a_module_created_in_a_folder_the_imports_were_resolved_in_is_seen(cli_real):
    _slam_project(cli_real)
    _age_folders(cli_real.project)
    cli_real("check", "--format", "json")
    assert len(list(cli_real.cache_dir.glob("imports-*.json"))) == 1
    cli_real.write("slam/geometry.py", _GEOMETRY)  # slam/'s mtime moves on
    second = cli_real("check", "--verbose", "--format", "json")
    assert counts(second.stderr) == (2, 2)
    assert [(f["path"], f["code"]) for f in json.loads(second.stdout)] == [("slam/mapping.py", "GEO101")]


def test_imports_resolved_in_folders_changed_just_now_are_not_stored(cli_real):
    """A file system clock may be too coarse to see a second change within the same tick."""
    _slam_project(cli_real)
    cli_real("check", "--format", "json")
    assert list(cli_real.cache_dir.glob("findings-*.json")) and not list(cli_real.cache_dir.glob("imports-*.json"))


def test_a_damaged_imports_cache_is_resolved_again(cli_real):
    _slam_project(cli_real)
    cli_real.write("slam/geometry.py", _GEOMETRY)
    _age_folders(cli_real.project)
    expected = cli_real("check", "--no-cache", "--format", "json").stdout
    cli_real("check", "--format", "json")
    (stored,) = cli_real.cache_dir.glob("imports-*.json")
    mapping = cli_real.project / "slam" / "mapping.py"
    damaged_entry = json.dumps({"folders": {}, "files": {str(mapping): [content_hash(mapping.read_bytes()), 5]}})
    for damage in ("{not json", '{"folders": [], "files": 3}', '{"files": {}}', "[]", damaged_entry):
        stored.write_text(damage)
        for finding in cli_real.cache_dir.glob("findings-*.json"):
            finding.unlink()
        assert cli_real("check", "--format", "json").stdout == expected


def test_a_run_that_reuses_some_imports_keeps_the_stamps_of_the_folders_they_were_resolved_in(cli_real):
    """`lib/` holds no Python file; only resolving app/main.py's import looks in it. A second run that
    reuses main.py's imports (and re-resolves only the edited other.py) must still watch `lib/`."""
    cli_real.write("setup.py", "")
    cli_real.write("lib/notes.txt", "")
    _write_importer(cli_real, "app/main.py", "lib.geo")
    cli_real.write("app/other.py", "x = 1\n")
    _age_folders(cli_real.project)
    assert json.loads(cli_real("check", "--format", "json").stdout) == []
    cli_real.write("app/other.py", "x = 2\n")  # edited in place: no folder changes
    assert counts(cli_real("check", "--verbose", "--format", "json").stderr) == (2, 1)
    cli_real.write("lib/geo.py", _GEOMETRY)  # lib/'s mtime moves on
    third = cli_real("check", "--verbose", "--format", "json")
    assert [(f["path"], f["code"]) for f in json.loads(third.stdout)] == [("app/main.py", "GEO101")]


_DECLARES = 'T_world_base = RigidTransform(R, t, from_frame="base", to_frame="world")\n'
_NAMES_ONLY = "def f(T_world_cam, p_base):\n    return T_world_cam @ p_base\n"


def _age_file(path, seconds: int = 3600) -> None:
    stamp = time.time() - seconds
    os.utime(path, (stamp, stamp))


def test_a_declaration_changed_in_one_file_relints_the_files_of_its_project(cli_real):
    """Names count as frames because poses.py states the convention; once it no longer does, planner.py
    (unchanged) must not be served its old finding."""
    cli_real.write("setup.py", "")
    cli_real.write("poses.py", _DECLARES)
    cli_real.write("planner.py", _NAMES_ONLY)
    first = cli_real("check", "--verbose", "--format", "json")
    assert [(f["path"], f["code"]) for f in json.loads(first.stdout)] == [("planner.py", "GEO201")]
    cli_real.write("poses.py", "T_world_base = load()\n")
    second = cli_real("check", "--verbose", "--format", "json")
    assert counts(second.stderr) == (0, 3) and json.loads(second.stdout) == []  # every file of the project relinted


def test_each_files_naming_votes_are_reused_while_its_stat_is_unchanged(cli_real):
    """The second run reads no file for its project's conventions: proven by an edit that keeps the file's
    size and mtime (nothing a real edit does), which the stored votes then do not see."""
    cli_real.write("setup.py", "")
    cli_real.write("poses.py", _DECLARES)
    cli_real.write("planner.py", _NAMES_ONLY)
    for name in ("setup.py", "poses.py", "planner.py"):
        _age_file(cli_real.project / name)
    first = cli_real("check", "--verbose", "--format", "json")
    assert len(json.loads(first.stdout)) == 1 and len(list(cli_real.cache_dir.glob("votes-*.json"))) == 1

    poses = cli_real.project / "poses.py"
    before = os.stat(poses)
    cli_real.write("poses.py", _DECLARES.replace("RigidTransform", "RigidTransfrom"))  # same size, no declaration
    os.utime(poses, ns=(before.st_atime_ns, before.st_mtime_ns))
    hidden = cli_real("check", "--verbose", "--format", "json")
    assert counts(hidden.stderr) == (2, 1)  # poses.py's bytes changed; planner.py's key (stored votes) did not
    assert [f["path"] for f in json.loads(hidden.stdout)] == ["planner.py"]


def test_naming_votes_of_files_written_just_now_are_not_stored(cli_real):
    cli_real.write("setup.py", "")
    cli_real.write("poses.py", _DECLARES)
    cli_real("check", "--verbose", "--format", "json")
    stored = json.loads(next(cli_real.cache_dir.glob("votes-*.json")).read_text())
    assert not any(path.endswith("poses.py") for path in stored)


def test_an_edit_that_leaves_the_projects_naming_reading_alone_relints_only_its_file(cli_real):
    cli_real.write("setup.py", "")
    cli_real.write("poses.py", _DECLARES)
    cli_real.write("planner.py", _NAMES_ONLY)
    cli_real("check", "--verbose", "--format", "json")
    cli_real.write("planner.py", _NAMES_ONLY + "T_world_tool = T_world_base @ T_base_tool\n")  # one more composition
    again = cli_real("check", "--verbose", "--format", "json")
    assert counts(again.stderr) == (2, 1)


def test_a_warm_run_lists_no_folder_while_every_folder_keeps_its_mtime(cli_real):
    """Proven by hiding a new module behind its folder's old mtime (nothing a real edit does): the
    reused listing does not know it, so nothing is linted."""
    cli_real.write("app/main.py", "x = 1\n")
    _age_folders(cli_real.project)
    first = cli_real("check", "--verbose", "--format", "json")
    assert counts(first.stderr) == (0, 1) and len(list(cli_real.cache_dir.glob("discovery-*.json"))) == 1
    app = cli_real.project / "app"
    before = os.stat(app)
    cli_real.write("app/hidden.py", "y = 2\n")
    os.utime(app, ns=(before.st_atime_ns, before.st_mtime_ns))
    assert counts(cli_real("check", "--verbose", "--format", "json").stderr) == (1, 0)


def test_a_file_added_or_removed_is_seen_by_the_next_run(cli_real):
    cli_real.write("app/main.py", "x = 1\n")
    _age_folders(cli_real.project)
    cli_real("check", "--format", "json")
    cli_real.write("app/new.py", "y = 2\n")  # app/'s mtime moves on
    assert counts(cli_real("check", "--verbose", "--format", "json").stderr) == (1, 1)
    _age_folders(cli_real.project)
    cli_real("check", "--format", "json")
    (cli_real.project / "app" / "main.py").unlink()
    assert re.search(r"files: 1,", cli_real("check", "--verbose", "--format", "json").stderr)


def test_a_gitignore_edited_in_place_changes_what_is_linted(cli_real):
    """Editing `.gitignore` leaves its folder's mtime alone: its own stamp is what tells."""
    cli_real.write(".gitignore", "generated/\n")
    cli_real.write("generated/out.py", "x = 1\n")
    cli_real.write("main.py", "y = 2\n")
    _age_folders(cli_real.project)
    _age_file(cli_real.project / ".gitignore")
    assert re.search(r"files: 1,", cli_real("check", "--verbose", "--format", "json").stderr)
    folder = os.stat(cli_real.project)
    (cli_real.project / ".gitignore").write_text("# nothing ignored\n")
    os.utime(cli_real.project, ns=(folder.st_atime_ns, folder.st_mtime_ns))
    assert re.search(r"files: 2,", cli_real("check", "--verbose", "--format", "json").stderr)


def test_listings_of_folders_changed_just_now_are_not_stored(cli_real):
    cli_real.write("app/main.py", "x = 1\n")
    cli_real("check", "--format", "json")
    assert list(cli_real.cache_dir.glob("findings-*.json")) and not list(cli_real.cache_dir.glob("discovery-*.json"))


def test_a_damaged_listing_walks_the_folders_again(cli_real):
    cli_real.write("app/main.py", "x = 1\n")
    cli_real.write("app/other.py", "x = 2\n")
    _age_folders(cli_real.project)
    cli_real("check", "--format", "json")
    (stored,) = cli_real.cache_dir.glob("discovery-*.json")
    for damage in ("{not json", "[]", '{"folders": {}, "files": {}, "links": {}, "sources": [["a.py"]]}', '{"folders": 3}'):
        stored.write_text(damage)
        assert re.search(r"files: 2,", cli_real("check", "--verbose", "--format", "json").stderr)


def test_files_named_one_by_one_store_no_listing(cli_real):
    """pre-commit names every staged file: each commit's list differs, and naming needs no walk."""
    cli_real.write("app/main.py", "x = 1\n")
    _age_folders(cli_real.project)
    cli_real("check", "--format", "json", "app/main.py")
    assert not list(cli_real.cache_dir.glob("discovery-*.json"))


def test_a_named_folder_that_is_a_link_is_listed_again_once_it_points_elsewhere(cli_real):
    cli_real.write("one/a.py", "x = 1\n")
    cli_real.write("two/a.py", "x = 1\n")
    cli_real.write("two/b.py", "x = 2\n")
    (cli_real.project / "current").symlink_to("one")
    _age_folders(cli_real.project)
    assert re.search(r"files: 1,", cli_real("check", "--verbose", "--format", "json", "current").stderr)
    link = cli_real.project / "current"
    folder = os.stat(cli_real.project)
    link.unlink()
    link.symlink_to("two")
    os.utime(cli_real.project, ns=(folder.st_atime_ns, folder.st_mtime_ns))  # only the link's target tells
    assert re.search(r"files: 2,", cli_real("check", "--verbose", "--format", "json", "current").stderr)
