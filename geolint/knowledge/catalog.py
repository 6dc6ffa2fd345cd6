"""The list of libraries the knowledge base covers, generated from `stubs/` (never written by hand).

    python -m geolint.knowledge.catalog > docs/libraries.md

A test fails when the committed page is out of date.
"""

from __future__ import annotations

from geolint.knowledge import Api, KnowledgeBase, knowledge_base

_FACTS = (
    ("quaternion order", lambda geometry: geometry.quaternion_order is not None),
    ("angle unit", lambda geometry: geometry.angle_unit is not None),
    ("points and vectors", lambda geometry: geometry.kind is not None and geometry.kind.value in ("point", "vector", "direction")),
    ("rotations and poses", lambda geometry: geometry.kind is not None and geometry.kind.value in ("rotation", "transform", "translation")),
    ("camera axes", lambda geometry: geometry.camera_axes is not None),
    ("array operations", lambda geometry: geometry.array_operation is not None),
)
# what a table row lists, in this order: the facts above, and the products a class's `__mul__` states
_LABELS = (*(label for label, _ in _FACTS), "products")


def _states(api: Api) -> set[str]:
    geometries = [
        geometry
        for signature in api.signatures
        for geometry in (signature.returns, *(parameter.geometry for parameter in signature.parameters))
        if geometry is not None
    ]
    geometries += [item for geometry in list(geometries) for item in geometry.items]
    stated = {label for label, test in _FACTS for geometry in geometries if test(geometry)}
    if any(signature.components for signature in api.signatures):
        stated.add("quaternion order")
    if api.qualified_name.endswith(".__mul__") and stated:
        stated.add("products")
    return stated


def catalog_markdown(kb: KnowledgeBase | None = None) -> str:
    kb = kb or knowledge_base()
    lines = [
        "# Libraries geolint knows",
        "",
        "Generated from `stubs/` by `python -m geolint.knowledge.catalog`; do not edit by hand. Each library",
        "is a folder of stubs stating what its APIs do with quaternions, angles, points and poses, each entry",
        "with its source; the linter and the mypy plugin read the same files. How to add one:",
        "[stubs/README.md](../stubs/README.md).",
        "",
        "For the libraries below, the linter answers from these stubs which component order a call reads or",
        "returns a quaternion in, and an attribute holds one in (GEO301 and the other quaternion rules), which",
        "arguments it reads in radians or degrees and in which unit it returns angles (GEO302, GEO305, GEO306,",
        "GEO307, with the keyword that says degrees as the fix), which arguments a transform call moves as points",
        "or as free vectors and the call or keyword that moves them the other way (GEO101, GEO102), which poses",
        "it reads as world-to-camera (GEO209) and in which camera axes (GEO216: Open3D's OpenCV axes, nerfstudio's",
        "OpenGL axes), and the kind of matrix a call returns; what a message or record",
        "field holds (`Twist.linear` is a free vector, px4_msgs `VehicleOdometry.q` is w, x, y, z), what `*` with a",
        "library pose does to what it multiplies (PyKDL's `Frame`, spatialmath's `SE3` translate it), which array",
        "functions transpose, invert and multiply matrices (numpy, torch, jax.numpy, cupy, tensorflow), and that",
        "a project importing Drake names poses in monogram notation. The mypy plugin reads the same quaternion",
        "orders (`geo-quaternion-order`) and moving calls. Some rules still read older tables of the fact base as",
        "well (the array namespaces' angle constants and padding, a few module names).",
        "",
        "| library | import names | checked against | APIs | what the stubs state |",
        "|---|---|---|---|---|",
    ]
    for name in sorted(kb.libraries, key=str.lower):
        library = kb.libraries[name]
        apis = [api for api in library.apis.values() if api.signatures or api.is_class]
        stated = set().union(*(_states(api) for api in apis)) if apis else set()
        facts = ", ".join(label for label in _LABELS if label in stated) or "-"
        packages = ", ".join(f"`{package}`" for package in library.packages)
        lines.append(f"| [{library.name}]({library.upstream}) | {packages} | {library.checked} | {len(apis)} | {facts} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    print(catalog_markdown(), end="")
