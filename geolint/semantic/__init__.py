"""The linter's semantic model: what a value in plain numpy code is (point, direction, transform)
and which frames it lives in, read from names, library calls and simple data flow.

`names` reads a single name; `model` reads a whole module once per file for all rules.
"""
