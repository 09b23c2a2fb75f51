#!/usr/bin/env python3
"""Markdown tables from one run of `cargo bench --bench dynamics` (criterion's JSON output).

    python3 bench/table.py [CRITERION_DIR] [--baseline NAME] [--compare OTHER]

CRITERION_DIR defaults to $CARGO_TARGET_DIR/criterion (or target/criterion). Times are
criterion's median estimate per call, in ns. Ratios are "how many times faster the generated
code is" (other / generated); for the floor, generated / floor. With --compare, a second table
gives the generated code's time under baseline OTHER divided by its time under NAME (the
speed-up between two saved runs).
"""
import argparse
import json
import os
import sys


def load(root, baseline):
    """{(group, function): median ns} for every benchmark saved under `baseline`."""
    out = {}
    for dirpath, _dirnames, filenames in os.walk(root):
        if os.path.basename(dirpath) != baseline or "estimates.json" not in filenames:
            continue
        try:
            with open(os.path.join(dirpath, "benchmark.json")) as f:
                meta = json.load(f)
            with open(os.path.join(dirpath, "estimates.json")) as f:
                est = json.load(f)
        except OSError:
            continue
        out[(meta["group_id"], meta["function_id"])] = est["median"]["point_estimate"]
    return out


def fmt(x):
    if x is None:
        return "-"
    return f"{x:.1f}" if x < 100 else f"{x:.0f}"


def ratio(a, b):
    if a is None or b is None or b == 0:
        return "-"
    return f"{a / b:.1f}x"


def groups(times):
    def key(g):
        s, _, n = g.partition("/N")
        return (s, int(n) if n.isdigit() else 0)

    return sorted({g for g, _ in times}, key=key)


def main():
    ap = argparse.ArgumentParser()
    default = os.path.join(os.environ.get("CARGO_TARGET_DIR", "target"), "criterion")
    ap.add_argument("root", nargs="?", default=default)
    ap.add_argument("--baseline", default="new")
    ap.add_argument("--compare")
    args = ap.parse_args()
    t = load(args.root, args.baseline)
    if not t:
        sys.exit(f"no criterion results under {args.root} (baseline {args.baseline})")

    def get(g, f):
        return t.get((g, f))

    print("Times in ns per call (criterion median); ratios = other / generated, except"
          " ID / floor = generated / floor.\n")
    def table(header, cells):
        """One markdown row per arm: "arm | N" and then `cells(group)`."""
        print("| arm | N | " + " | ".join(header) + " |")
        print("|" + "---|" * (len(header) + 2))
        for g in groups(t):
            s, _, n = g.partition("/N")
            print("| " + " | ".join([s, n] + cells(g)) + " |")

    def inverse_dynamics(g):
        floor, kfloor = get(g, "floor/sin_cos"), get(g, "floor/trig_kernel")
        gid = get(g, "generated/inverse_dynamics")
        rnea, rbt = get(g, "reference/rnea"), get(g, "reference/rnea_batched_trig")
        did = get(g, "dynibo/inverse_dynamics")
        return [fmt(floor), fmt(kfloor), fmt(gid), ratio(gid, floor), ratio(gid, kfloor),
                fmt(rnea), ratio(rnea, gid), fmt(rbt), ratio(rbt, gid), fmt(did), ratio(did, gid)]

    def others(g):
        gm, gfd = get(g, "generated/mass_matrix"), get(g, "generated/forward_dynamics")
        crba, aba = get(g, "reference/crba"), get(g, "reference/aba")
        dm, dfd = get(g, "dynibo/mass_matrix"), get(g, "dynibo/forward_dynamics")
        cg = get(g, "generated/coriolis+gravity")
        return [fmt(gm), fmt(crba), ratio(crba, gm), fmt(dm), ratio(dm, gm), fmt(cg),
                fmt(gfd), fmt(aba), ratio(aba, gfd), fmt(dfd), ratio(dfd, gfd)]

    print("Inverse dynamics:\n")
    table(["floor: N f64::sin_cos", "floor: trig::sin_cos", "gen ID", "ID / floor (sin_cos)",
           "ID / floor (trig)", "RNEA", "RNEA / gen", "RNEA, batched trig", "RNEA bt / gen",
           "dynibo ID", "dynibo / gen"], inverse_dynamics)
    print("\nMass matrix, bias and forward dynamics:\n")
    table(["gen M", "CRBA", "CRBA / gen", "dynibo M", "dynibo / gen", "gen c+g", "gen FD", "ABA",
           "ABA / gen", "dynibo FD", "dynibo / gen"], others)

    if args.compare:
        old = load(args.root, args.compare)
        methods = [("ID", "inverse_dynamics"), ("M", "mass_matrix"), ("c+g", "coriolis+gravity"),
                   ("FD", "forward_dynamics")]

        def speed_up(g):
            row = []
            for _, f in methods:
                a, b = old.get((g, "generated/" + f)), t.get((g, "generated/" + f))
                row += [fmt(a), fmt(b), ratio(a, b)]
            return row

        print(f"\nGenerated code, {args.compare} / {args.baseline} (speed-up of the generated code;"
              " two runs, so noisier than the ratios above):\n")
        table([h for m, _ in methods for h in (f"{m} before", f"{m} after", "speed-up")], speed_up)

if __name__ == "__main__":
    main()
