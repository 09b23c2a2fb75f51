#!/usr/bin/env python3
"""How long SymPy takes to derive an N-link planar arm's equations of motion the way a user
typically would: Lagrange's equation on a Cartesian kinetic/potential energy, then M, c, g,
tidied only with expand + trigsimp.

Run by hand (not in CI):  pip install sympy && python3 bench/sympy_lagrange.py [MAX_N] [--budget S]
MAX_N defaults to 8 (at most 12); --budget stops before starting a new N once the total time
spent exceeds S seconds. Parameters are random rationals from a fixed seed (--seed), so runs are
repeatable: uniform rods (inertia m l^2/12 about the centre, centre at l/2), gravity 981/100 along -y.

"terms in M" is the total number of additive terms over all N*N entries of M after
expand + trigsimp.

Measured 2026-11-22 on a 2-core machine (SymPy 1.14.0, Python 3.11.7, seed 2026), command
`python3 bench/sympy_lagrange.py 6 --budget 240`:

    | N | seconds | terms in M |
    |---|---|---|
    | 1 | 0.08 | 1 |
    | 2 | 0.66 | 7 |
    | 3 | 4.61 | 25 |
    | 4 | 34.28 | 66 |
    | 5 | 371.33 | 145 |
    total 410.9 s; stopped before N = 6 (budget). Each step costs ~7-11x the last, so
    N = 6 would take roughly an hour; N <= 4 fits in under a minute.

Almost all of the time is trigsimp (N = 4 with expand alone: 1.2 s instead of 34 s); the
trigsimp'd M is fully reduced (N = 3 gives the 25 terms of the hand-derived matrix).
"""
import argparse
import random
import sys
import time

import sympy as sp


def build_arm(n, rng):
    t = sp.Symbol("t")
    q = [sp.Function(f"q{i + 1}")(t) for i in range(n)]
    lengths = [sp.Rational(rng.randint(5, 20), 10) for _ in range(n)]
    masses = [sp.Rational(rng.randint(5, 30), 10) for _ in range(n)]
    grav = sp.Rational(981, 100)
    angle = sp.Integer(0)
    jx = sp.Integer(0)
    jy = sp.Integer(0)
    kinetic = sp.Integer(0)
    potential = sp.Integer(0)
    for i in range(n):
        angle = angle + q[i]
        l, m = lengths[i], masses[i]
        inertia = m * l**2 / 12
        cx = jx + l / 2 * sp.cos(angle)
        cy = jy + l / 2 * sp.sin(angle)
        vx, vy, w = sp.diff(cx, t), sp.diff(cy, t), sp.diff(angle, t)
        kinetic += sp.Rational(1, 2) * m * (vx**2 + vy**2) + sp.Rational(1, 2) * inertia * w**2
        potential += m * grav * cy
        jx += l * sp.cos(angle)
        jy += l * sp.sin(angle)
    return t, q, kinetic, potential


def tidy(e):
    return sp.trigsimp(sp.expand(e))


def derive(n, rng):
    t, q, kinetic, potential = build_arm(n, rng)
    lagrangian = kinetic - potential
    qd = [sp.diff(qi, t) for qi in q]
    qdd = [sp.diff(qi, t, 2) for qi in q]
    # Lagrange's equation: tau_i = d/dt dL/dqd_i - dL/dq_i
    tau = sp.Matrix([sp.diff(sp.diff(lagrangian, qd[i]), t) - sp.diff(lagrangian, q[i])
                     for i in range(n)])
    mass = tau.jacobian(qdd).applyfunc(tidy)
    grav = sp.Matrix([sp.diff(potential, qi) for qi in q]).applyfunc(tidy)
    zero_acc = {a: 0 for a in qdd}
    cor = (tau.subs(zero_acc) - grav).applyfunc(tidy)
    return mass, cor, grav


def count_terms(mat):
    return sum(len(sp.Add.make_args(e)) for e in mat)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("max_n", nargs="?", type=int, default=8, help="largest N (1..12, default 8)")
    ap.add_argument("--budget", type=float, default=None,
                    help="do not start a new N once this many seconds have been spent in total")
    ap.add_argument("--seed", type=int, default=2026)
    args = ap.parse_args()
    max_n = max(1, min(12, args.max_n))
    rng = random.Random(args.seed)
    print(f"# SymPy {sp.__version__}, Python {sys.version.split()[0]}: N-link planar arm, "
          "Lagrange's equation, expand + trigsimp")
    print("| N | seconds | terms in M |")
    print("|---|---|---|", flush=True)
    total = 0.0
    for n in range(1, max_n + 1):
        if args.budget is not None and total > args.budget:
            print(f"# stopped: {total:.1f} s spent, budget {args.budget:.0f} s", flush=True)
            break
        start = time.perf_counter()
        mass, cor, grav = derive(n, rng)
        secs = time.perf_counter() - start
        total += secs
        # sanity: M symmetric, g has no velocities
        assert all(sp.expand(mass[i, j] - mass[j, i]) == 0 for i in range(n) for j in range(i))
        print(f"| {n} | {secs:.2f} | {count_terms(mass)} |", flush=True)
    print(f"# total {total:.1f} s", flush=True)


if __name__ == "__main__":
    main()
