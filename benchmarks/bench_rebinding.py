"""Linter cost of rebinding-heavy scopes, small and large side by side in one run (medians of repeats).

Two generated shapes, each at a small and a large size (statements):

- `function`: one function that rebinds four names over and over (`p_world = T_world_cam @ p_cam`,
  `T_world_cam = T_world_cam @ np.eye(4)`, ...), as generated code does;
- `script`: a long module-level script, as notebooks and experiment scripts are written: blocks
  of poses, points, angles and quaternions with names of their own and names rebound by every
  block, branches, loops, prints and a helper function now and then.

Each figure is the CPU time of one `geolint.api.lint_text` of the file with every rule, measured
in a fresh process (start-up and imports not counted), so caches never carry from one run to the
next. Each repeat is a round that measures every row once, so drift hits all alike; the figures are
medians over the rounds, and large/small ratios are taken within each round. Linear cost puts the
ratio at the size ratio (10 by default); the check is that it stays within 2x of that.

    python benchmarks/bench_rebinding.py                       # 1,000 and 10,000 statements, 3 rounds
    python benchmarks/bench_rebinding.py --repeats 5 --shape function
    python benchmarks/bench_rebinding.py --small 500 --large 5000 --keep /tmp/generated
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

# Run in a fresh interpreter: import first, lint a line (tables built once), then time the lint.
_CHILD = """
import json, sys, time
from pathlib import Path
from geolint.api import lint_text
source = Path(sys.argv[1]).read_text(encoding="utf-8")
lint_text("x = 1\\n")
start = time.process_time()
findings = lint_text(source, sys.argv[1])
print(json.dumps({"cpu": time.process_time() - start, "findings": len(findings)}))
"""


def rebinding_function(statements: int) -> str:
    """One function of `statements` statements that rebind four names in turn."""
    rounds = statements // 4
    lines = ["import numpy as np", "", "", "def step(T_world_cam, p_cam, origin):"]
    for _ in range(rounds):
        lines += [
            "    p_world = T_world_cam @ p_cam",
            "    v = p_world - origin",
            "    T_world_cam = T_world_cam @ np.eye(4)",
            "    p_cam = v + origin",
        ]
    lines.append("    return p_world, v")
    return "\n".join(lines) + "\n"


_SCRIPT_HEAD = """\
import math

import numpy as np
from scipy.spatial.transform import Rotation

T_world_base = np.eye(4)
origin = np.zeros(3)
total = 0.0
results = []
"""

# One block of the script (`{k}` numbers its own names); 20 statements, nested ones included.
_SCRIPT_BLOCK = """\

# step {k}
pose_{k} = np.loadtxt("poses/{k}.txt").reshape(4, 4)
T_world_cam = T_world_base @ pose_{k}
p_cam = np.array([{k}.0, 0.0, 1.0])
p_world = T_world_cam[:3, :3] @ p_cam + T_world_cam[:3, 3]
heading = math.atan2(p_world[1], p_world[0])
yaw_deg = math.degrees(heading)
R = Rotation.from_euler("z", yaw_deg, degrees=True)
q = R.as_quat()
x, y, z, w = q
orientation_{k} = [w, x, y, z]
if yaw_deg > 90:
    direction = p_world - origin
    direction = direction / np.linalg.norm(direction)
else:
    direction = np.zeros(3)
for j in range(3):
    total = total + p_world[j]
print("step", {k}, p_world, yaw_deg)
results.append((p_world, orientation_{k}, direction))
"""
_SCRIPT_BLOCK_STATEMENTS = 20
_HELPER = """\


def to_world_{k}(p):
    return T_world_cam[:3, :3] @ p + T_world_cam[:3, 3]

"""


def long_script(statements: int) -> str:
    """A module-level script of about `statements` statements (a helper function every tenth block)."""
    parts = [_SCRIPT_HEAD]
    for k in range(statements // _SCRIPT_BLOCK_STATEMENTS):
        parts.append(_SCRIPT_BLOCK.format(k=k))
        if k % 10 == 9:
            parts.append(_HELPER.format(k=k))
    return "".join(parts)


SHAPES = {"function": rebinding_function, "script": long_script}


def lint_cpu(path: Path) -> tuple[float, int]:
    """(CPU seconds of the lint, findings) in a fresh process."""
    result = subprocess.run([sys.executable, "-c", _CHILD, str(path)], capture_output=True, text=True, check=False)
    if result.returncode != 0:
        raise SystemExit(f"lint of {path} failed:\n{result.stderr[-2000:]}")
    answer = json.loads(result.stdout.strip().splitlines()[-1])
    return float(answer["cpu"]), int(answer["findings"])


def main() -> int:
    sys.stdout.reconfigure(line_buffering=True)  # type: ignore[attr-defined]  # progress shows when piped
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--small", type=int, default=1_000, help="statements of the small file (default 1,000)")
    parser.add_argument("--large", type=int, default=10_000, help="statements of the large file (default 10,000)")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--shape", choices=[*SHAPES, "all"], default="all")
    parser.add_argument("--keep", type=Path, default=None, help="write the generated files here and keep them")
    args = parser.parse_args()

    shapes = list(SHAPES) if args.shape == "all" else [args.shape]
    folder = args.keep or Path(tempfile.mkdtemp(prefix="geolint-rebinding-"))
    folder.mkdir(parents=True, exist_ok=True)
    files: dict[tuple[str, int], Path] = {}
    for shape in shapes:
        for size in (args.small, args.large):
            path = folder / f"{shape}_{size}.py"
            path.write_text(SHAPES[shape](size), encoding="utf-8")
            files[shape, size] = path
    print(f"date: {time.strftime('%Y-%m-%d %H:%M')} (figures are medians of {args.repeats} rounds; a shared machine adds noise)")
    print(f"load average at start: {' '.join(f'{value:.2f}' for value in os.getloadavg())}")
    runs: dict[tuple[str, int], list[float]] = {key: [] for key in files}
    found: dict[tuple[str, int], int] = {}
    for round_number in range(1, args.repeats + 1):
        for key, path in files.items():
            cpu, found[key] = lint_cpu(path)
            runs[key].append(cpu)
        print(f"round {round_number}: " + ", ".join(f"{shape} {size} {runs[shape, size][-1]:.2f} s" for shape, size in files))
    wanted = args.large / args.small
    print(f"{'shape':10} {'statements':>10} {'lines':>8} {'findings':>9} {'CPU s':>8} {'statements/CPU s':>17}")
    for (shape, size), path in files.items():
        cpu = statistics.median(runs[shape, size])
        lines = path.read_text(encoding="utf-8").count("\n")
        print(f"{shape:10} {size:10,} {lines:8,} {found[shape, size]:9,} {cpu:8.2f} {size / cpu:17,.0f}")
    for shape in shapes:
        ratios = [large / small for small, large in zip(runs[shape, args.small], runs[shape, args.large])]
        ratio = statistics.median(ratios)
        verdict = "within" if ratio <= 2 * wanted else "NOT within"
        print(
            f"{shape}: large/small per round {', '.join(f'{r:.1f}x' for r in ratios)}, median {ratio:.1f}x "
            f"for {wanted:.0f}x the statements ({verdict} 2x of {wanted:.0f}x)"
        )
    print(f"load average at end: {' '.join(f'{value:.2f}' for value in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
