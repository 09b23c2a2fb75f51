#!/usr/bin/env python3
"""The run-time cost of parameters: a Markdown table from one run of
`cargo bench --bench parameters` (criterion's JSON output).

    python3 bench/parameters_table.py [CRITERION_DIR]

Each cell is the parameterised arm's median time over its literal twin's (1.00 = no cost).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from table import load  # noqa: E402  (one loader for every table)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.environ.get("CARGO_TARGET_DIR", "target"), "criterion")
    times = load(root, "new")
    print("| N | ID params / literal | M params / literal | FD params / literal | ID literal ns |")
    print("|---|---|---|---|---|")
    for n in (2, 3, 4, 6):
        group = f"parameters/{n}"
        row = [str(n)]
        for what in ("id", "m", "fd"):
            lit = times.get((group, f"{what}/literal"))
            par = times.get((group, f"{what}/params"))
            row.append(f"{par / lit:.2f}" if lit and par else "-")
        lit = times.get((group, "id/literal"))
        row.append(f"{lit:.1f}" if lit else "-")
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
