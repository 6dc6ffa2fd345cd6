"""Benchmark: the geolint runtime against the fastest plain-numpy kernel for the same work.

Run: ``python benchmarks/bench_runtime.py`` (``--quick`` for fewer repeats). Single-threaded BLAS, medians
of repeats, every case measured side by side in one run. Targets (issue 2): one transform on 1,000,000
points <= 1.2x, one transform on one point <= 2x, composing two transforms <= 2x, composing 100,000 pose
pairs in a batch <= 1.5x.
"""

from __future__ import annotations

import os

# Before numpy is imported: one BLAS thread, so the comparison measures our overhead, not thread scheduling.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "BLIS_NUM_THREADS", "VECLIB_MAXIMUM_THREADS"):
    os.environ[_var] = "1"

import argparse
import datetime
import platform
import statistics
import timeit
from collections.abc import Callable

import numpy as np

from geolint import Point, Transform


def _cpu_name() -> str:
    try:
        with open("/proc/cpuinfo") as cpuinfo:
            for line in cpuinfo:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def median_seconds(funcs: dict[str, Callable[[], object]], number: int, repeat: int) -> dict[str, float]:
    """Median time of one call of each function, measured round-robin (side by side).

    Each of ``repeat`` rounds times ``number`` calls of every function in turn, so a change of machine load
    during the run hits all candidates alike instead of skewing one of them.
    """
    timers = {name: timeit.Timer(func) for name, func in funcs.items()}
    for timer in timers.values():
        timer.timeit(number=1)  # warm-up: caches, lazily built views
    samples: dict[str, list[float]] = {name: [] for name in funcs}
    for _ in range(repeat):
        for name, timer in timers.items():
            samples[name].append(timer.timeit(number=number) / number)
    return {name: statistics.median(times) for name, times in samples.items()}


def random_poses(rng: np.random.Generator, n: int) -> np.ndarray:
    """``n`` random rigid 4x4 matrices (rotations from QR of Gaussian matrices, det fixed to +1)."""
    q, r = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    q *= np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :]
    q[np.linalg.det(q) < 0, :, 0] *= -1
    m = np.zeros((n, 4, 4))
    m[:, :3, :3] = q
    m[:, :3, 3] = rng.normal(size=(n, 3))
    m[:, 3, 3] = 1.0
    return m


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats (for a smoke run)")
    args = parser.parse_args()
    repeat = 5 if args.quick else 31

    rng = np.random.default_rng(0)
    pose = random_poses(rng, 1)[0]
    pose2 = random_poses(rng, 1)[0]
    R, t = np.ascontiguousarray(pose[:3, :3]), np.ascontiguousarray(pose[:3, 3])
    T = Transform["world", "camera"].from_matrix(pose)
    T2 = Transform["camera", "tool"].from_matrix(pose2)

    rows: list[tuple[str, str, float, float, float]] = []

    # 1. One transform on 1,000,000 points.
    pts = rng.normal(size=(1_000_000, 3))
    batch = Point["camera"](pts)
    preallocated = np.empty_like(pts)
    Rt = np.ascontiguousarray(R.T)

    def into_preallocated() -> np.ndarray:
        np.matmul(pts, R.T, out=preallocated)
        np.add(preallocated, t, out=preallocated)
        return preallocated

    def matmul_then_add_inplace() -> np.ndarray:
        result = pts @ Rt
        result += t
        return result

    def transposed_matmul_then_add_inplace() -> np.ndarray:
        result = (R @ pts.T).T
        result += t
        return result

    kernels = {
        "pts @ R.T + t": lambda: pts @ R.T + t,
        "(R @ pts.T).T + t": lambda: (R @ pts.T).T + t,
        "matmul into preallocated out, += t": into_preallocated,
        "pts @ R.T, then += t": matmul_then_add_inplace,
        "(R @ pts.T).T, then += t": transposed_matmul_then_add_inplace,
    }
    assert np.allclose(np.asarray(T @ batch), pts @ R.T + t)
    timings = median_seconds({**kernels, "geolint": lambda: T @ batch}, 3, repeat)
    ours = timings.pop("geolint")
    fastest = min(timings, key=timings.__getitem__)
    rows.append(("T @ Point batch (1,000,000 points)", fastest, timings[fastest], ours, 1.2))
    kernel_lines = [f"    {name:<38} {sec * 1e3:8.2f} ms" for name, sec in timings.items()]

    # 2. One transform on one point.
    p = rng.normal(size=3)
    point = Point["camera"](p)
    number = 20_000
    timed = median_seconds({"numpy": lambda: R @ p + t, "geolint": lambda: T @ point}, number, repeat)
    rows.append(("T @ Point (one point)", "R @ p + t", timed["numpy"], timed["geolint"], 2.0))

    # 3. Composing two transforms.
    timed = median_seconds({"numpy": lambda: pose @ pose2, "geolint": lambda: T @ T2}, number, repeat)
    rows.append(("T_ab @ T_bc (one pair)", "A @ B (4x4)", timed["numpy"], timed["geolint"], 2.0))

    # 4. Composing 100,000 pose pairs.
    a, b = random_poses(rng, 100_000), random_poses(rng, 100_000)
    Ta = Transform["world", "camera"].from_matrix(a)
    Tb = Transform["camera", "tool"].from_matrix(b)
    assert np.allclose(np.asarray(Ta @ Tb), a @ b)
    timed = median_seconds({"numpy": lambda: a @ b, "geolint": lambda: Ta @ Tb}, 3, repeat)
    rows.append(("T_ab @ T_bc (batch of 100,000)", "np.matmul (N,4,4)", timed["numpy"], timed["geolint"], 1.5))

    print(f"geolint runtime benchmark, {datetime.date.today().isoformat()}, {platform.machine()}, {_cpu_name()}")
    print(f"numpy {np.__version__}, single-threaded BLAS, median of {repeat} round-robin repeats\n")
    print("plain-numpy kernels for 1,000,000 points:")
    print("\n".join(kernel_lines))
    print()
    header = f"| {'case':<34} | {'plain numpy (fastest)':<36} | {'numpy':>10} | {'geolint':>10} | {'ratio':>5} | {'target':>6} |"
    print(header)
    print("|" + "|".join("-" * (len(cell)) for cell in header.split("|")[1:-1]) + "|")
    for case, baseline, plain_s, ours_s, target in rows:
        ratio = ours_s / plain_s
        verdict = "ok" if ratio <= target else "MISSED"
        target_text = f"<= {target}"
        print(
            f"| {case:<34} | {baseline:<36} | {_fmt(plain_s):>10} | {_fmt(ours_s):>10} | {ratio:5.2f} | "
            f"{target_text:>6} | {verdict}"
        )


def _fmt(seconds: float) -> str:
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.2f} ms"
    return f"{seconds * 1e6:.2f} us"


if __name__ == "__main__":
    main()
