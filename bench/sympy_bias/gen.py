#!/usr/bin/env python3
"""Writes src/sympy_generated.rs: M(q) and h(q, qd) = c + g of N uniform rods (N = 2..8) as
straight-line Rust produced with SymPy, for the by-hand benchmark in src/main.rs (README.md).

Run by hand:  python3 gen.py [MAX_N]        (MAX_N defaults to 8; about 5 minutes for 2..8 on the 2-core machine)

Pipeline, as a typical sympy.physics.mechanics user would write it:
  - frames A_i = A_{i-1} rotated by q_i about z (relative angles; A_0 the inertial frame N),
    joints and centres of mass located along A_i.x, velocities by v2pt_theory;
  - RigidBody per link (mass 1, inertia 1/12 about the centre, centre at 1/2), potential energy
    m g y with g = 981/100 along -y;
  - L = Lagrangian(N, *bodies); LagrangesMethod(L, q).form_lagranges_equations();
    M = lm.mass_matrix, h = -lm.forcing (no input torques, so tau = M qdd + h);
  - dynamicsymbols -> plain symbols (msubs); then ONE sympy.cse over the upper triangle of M
    and all of h together. No simplify/trigsimp.

Three variants per N go into the file:
  raw_N           cse of the expressions exactly as LagrangesMethod gives them (the headline);
  expanded_N      the same after sympy.expand of every entry (then cse);
  raw_fasttrig_N  raw_N's arithmetic, but sin/cos(q_k) taken from planar_arm::trig::sin_cos
                  (the crate's batched trig kernel) instead of f64::sin / f64::cos: not what
                  SymPy emits, only to separate trigonometry from arithmetic.

The Rust is printed by `RustPrinter` below, not sympy.printing.rust (SymPy 1.14's Rust printer
drops parentheses, sympy issue #28776): every compound subexpression is parenthesised
explicitly. src/main.rs checks every function against the derive at random states.
"""
import sys
import time

import sympy as sp
from sympy.physics.mechanics import (LagrangesMethod, Lagrangian, Point, ReferenceFrame,
                                     RigidBody, dynamicsymbols, inertia, msubs)


def derive(n):
    """(M, h) of n uniform unit rods as LagrangesMethod gives them, in plain symbols q0.., qd0.."""
    q = dynamicsymbols(f"q1:{n + 1}")
    qd = dynamicsymbols(f"q1:{n + 1}", 1)
    length, mass, grav = sp.Integer(1), sp.Integer(1), sp.Rational(981, 100)
    frame_n = ReferenceFrame("N")
    origin = Point("O")
    origin.set_vel(frame_n, 0)
    prev, joint, bodies = frame_n, origin, []
    for i in range(n):
        frame = ReferenceFrame(f"A{i + 1}")
        frame.orient_axis(prev, prev.z, q[i])
        centre = joint.locatenew(f"G{i + 1}", length / 2 * frame.x)
        centre.v2pt_theory(joint, frame_n, frame)
        body = RigidBody(f"B{i + 1}", centre, frame, mass,
                         (inertia(frame, 0, 0, mass * length**2 / 12), centre))
        body.potential_energy = mass * grav * centre.pos_from(origin).dot(frame_n.y)
        bodies.append(body)
        nxt = joint.locatenew(f"P{i + 1}", length * frame.x)
        nxt.v2pt_theory(joint, frame_n, frame)
        prev, joint = frame, nxt
    lm = LagrangesMethod(Lagrangian(frame_n, *bodies), q)
    lm.form_lagranges_equations()
    qs = sp.symbols(f"q0:{n}")
    qds = sp.symbols(f"qd0:{n}")
    sub = dict(zip(qd, qds))
    sub.update(zip(q, qs))
    m = [[msubs(lm.mass_matrix[i, j], sub) for j in range(n)] for i in range(n)]
    h = [msubs(-lm.forcing[i], sub) for i in range(n)]
    return qs, qds, m, h


class RustPrinter:
    """Straight-line Rust for the node types cse leaves here, every compound node in parens."""

    def __init__(self, trig):
        self.trig = trig  # "std": x.sin() / x.cos();  "vars": s{k} / c{k} from a preamble

    def num(self, r):
        if r.q == 1:
            return f"{r.p}.0"
        return f"({r.p}.0 / {r.q}.0)"

    def __call__(self, e):
        if e.is_Symbol:
            return e.name
        if e.is_Rational:
            return self.num(e)
        if e.is_Float:
            return repr(float(e))
        if isinstance(e, (sp.sin, sp.cos)):
            (arg,) = e.args
            if self.trig == "vars":
                assert arg.is_Symbol and arg.name.startswith("q"), e
                return f"{'s' if isinstance(e, sp.sin) else 'c'}{arg.name[1:]}"
            return f"{self(arg)}.{'sin' if isinstance(e, sp.sin) else 'cos'}()"
        if e.is_Add:
            return "(" + " + ".join(self(a) for a in e.args) + ")"
        if e.is_Mul:
            coeff, rest = e.as_coeff_Mul()
            if coeff == -1:
                return f"(-{self(rest)})"
            return "(" + " * ".join(self(a) for a in e.args) + ")"
        if e.is_Pow:
            base, ex = e.args
            if ex.is_Integer and ex > 0:
                return f"{self(base)}.powi({ex})"
            if ex.is_Integer and ex < 0:
                return f"(1.0 / {self(base)}.powi({-ex}))"
            if ex == sp.Rational(1, 2):
                return f"{self(base)}.sqrt()"
            raise ValueError(f"unsupported power {e}")
        raise ValueError(f"unsupported node {type(e).__name__}: {e}")


def emit(name, n, reps, reduced, trig):
    pr = RustPrinter(trig)
    out = [f"#[inline]\n#[allow(clippy::all, unused_variables, unused_parens)]\n"
           f"pub fn {name}(q: &SVector<f64, {n}>, qd: &SVector<f64, {n}>) "
           f"-> (SMatrix<f64, {n}, {n}>, SVector<f64, {n}>) {{"]
    for k in range(n):
        out.append(f"    let q{k} = q[{k}];")
        out.append(f"    let qd{k} = qd[{k}];")
    if trig == "vars":
        lhs = ", ".join(f"(s{k}, c{k})" for k in range(n))
        args = ", ".join(f"q{k}" for k in range(n))
        out.append(f"    let [{lhs}] = planar_arm::trig::sin_cos([{args}]);")
    for sym, val in reps:
        out.append(f"    let {sym.name} = {pr(val)};")
    upper = reduced[: n * (n + 1) // 2]
    h = reduced[n * (n + 1) // 2:]
    idx = {}
    k = 0
    for i in range(n):
        for j in range(i, n):
            out.append(f"    let m{i}_{j} = {pr(upper[k])};")
            idx[(i, j)] = idx[(j, i)] = f"m{min(i, j)}_{max(i, j)}"
            k += 1
    for i in range(n):
        out.append(f"    let h{i} = {pr(h[i])};")
    cols = ", ".join(idx[(i, j)] for j in range(n) for i in range(n))  # column-major
    out.append(f"    (SMatrix::<f64, {n}, {n}>::from_column_slice(&[{cols}]),")
    out.append(f"     SVector::<f64, {n}>::from_column_slice(&[{', '.join(f'h{i}' for i in range(n))}]))")
    out.append("}\n")
    return "\n".join(out)


def count_ops(reps, reduced):
    return sum(sp.count_ops(v) for _, v in reps) + sum(sp.count_ops(e) for e in reduced)


def main():
    max_n = int(sys.argv[1]) if len(sys.argv) > 1 else 8
    header = [
        "// @generated by bench/sympy_bias/gen.py: do not edit.",
        f"// SymPy {sp.__version__}, Python {sys.version.split()[0]}.",
        "// LagrangesMethod -> M, h = -forcing -> (raw | expand) -> one cse over M's upper",
        "// triangle and h -> explicit-parenthesis printer (gen.py). Per N:",
        "//   N | derive s | raw: cse s, lets, ops | expanded: expand s, cse s, lets, ops",
    ]
    bodies = []
    for n in range(2, max_n + 1):
        t0 = time.perf_counter()
        _, _, m, h = derive(n)
        t1 = time.perf_counter()
        exprs = [m[i][j] for i in range(n) for j in range(i, n)] + h
        reps, reduced = sp.cse(exprs)
        t2 = time.perf_counter()
        bodies.append(emit(f"raw_{n}", n, reps, reduced, "std"))
        bodies.append(emit(f"raw_fasttrig_{n}", n, reps, reduced, "vars"))
        raw_ops = count_ops(reps, reduced)
        raw_lets = len(reps)
        t3 = time.perf_counter()
        expanded = [sp.expand(e) for e in exprs]
        t4 = time.perf_counter()
        reps_e, reduced_e = sp.cse(expanded)
        t5 = time.perf_counter()
        bodies.append(emit(f"expanded_{n}", n, reps_e, reduced_e, "std"))
        line = (f"//   {n} | {t1 - t0:.1f} | {t2 - t1:.2f}, {raw_lets}, {raw_ops} | "
                f"{t4 - t3:.1f}, {t5 - t4:.2f}, {len(reps_e)}, {count_ops(reps_e, reduced_e)}")
        header.append(line)
        print(line[5:], file=sys.stderr, flush=True)
    header.append("// (ops: sympy.count_ops summed over the cse bindings and outputs; only M's upper")
    header.append("// triangle is computed, the lower is mirrored.)")
    text = "\n".join(header) + "\n\nuse planar_arm::nalgebra::{SMatrix, SVector};\n\n" + "\n".join(bodies)
    with open("src/sympy_generated.rs", "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
