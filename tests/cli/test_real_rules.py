"""The plain `python -m geolint` with only the real rules: the JSON contract and a safe fix end to end."""

from __future__ import annotations

import ast
import json

from tests.conftest import DECLARES_DST_FIRST

BUGGY = (
    "import numpy as np\n"
    "from scipy.spatial.transform import Rotation\n"
    "\n"
    "\n"
    "def yaw_half_turn():\n"
    '    return Rotation.from_euler("z", 180).as_matrix()\n'
    "\n"
    "\n"
    "def to_world(T_world_base, p_cam):\n"
    "    return T_world_base @ np.append(p_cam, 1.0)\n"
) + DECLARES_DST_FIRST


def test_real_findings_follow_the_json_contract_and_fix_to_a_fixed_point(cli_real):
    path = cli_real.write("robot.py", BUGGY)
    result = cli_real("check", "--format", "json")
    assert result.returncode == 1, result.stderr
    findings = json.loads(result.stdout)
    codes = {f["code"] for f in findings}
    assert {"GEO302", "GEO201"} <= codes
    for finding in findings:
        assert set(finding) - {"evidence", "frames"} == {
            "path", "line", "column", "end_line", "end_column", "code", "name", "message", "severity", "fix",
        }  # fmt: skip
        assert all(isinstance(reason, str) for reason in finding.get("evidence", []))  # optional: why
        # optional, frame mismatches only: the frame the operation needs and the one it got
        assert "frames" not in finding or (finding["code"].startswith("GEO2") and len(finding["frames"]) == 2)
        assert finding["path"] == "robot.py"
        assert finding["severity"] in {"error", "warning", "info", "hint"}

    fixed = cli_real("check", "--fix", "--format", "json")
    text = path.read_text()
    ast.parse(text)
    assert "degrees=True" in text
    assert "GEO302" not in {f["code"] for f in json.loads(fixed.stdout)}
    again = cli_real("check", "--fix", "--exit-non-zero-on-fix", "--select", "GEO302")
    assert again.returncode == 0 and path.read_text() == text  # idempotent


def test_demo_fixtures_show_findings(cli_real):
    from pathlib import Path

    demo = Path(__file__).resolve().parents[2] / "fixtures" / "demo"
    result = cli_real("check", str(demo), "--no-cache", "--format", "json")
    assert result.returncode == 1
    assert len({f["code"] for f in json.loads(result.stdout)}) >= 3
