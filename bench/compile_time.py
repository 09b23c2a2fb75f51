#!/usr/bin/env python3
"""What deriving an arm costs a user's build: the table in docs/performance.md.

For each arm size it writes a binary crate (in a temporary directory, depending on this
repository by path, default `dev` profile, no profile settings) that derives one arm and calls
its inverse dynamics, forward dynamics, mass matrix and bias once (so those are compiled, not
only type-checked; with `--derivatives` also `linearize`, which calls the derivatives),
builds it once to compile the dependencies, then times
`cargo clean -p <crate>` followed by `cargo build`: a clean rebuild of that crate alone. Peak
memory is the largest resident size of any process of the build (GNU time's %M).

Arms: lengths 2/4, 3/4, 4/4, ... and literal masses, inertias and centres of mass; with
`params`, masses, inertias and centres are run-time parameters (`self.m0`, ...); with
`--lengths`, the parameterised arms' lengths too (`self.len0`, ...).

    python3 bench/compile_time.py                 # 6 10 14 20 30 links, literal and parameterised
    python3 bench/compile_time.py 6 10 --runs 3   # chosen sizes, best of three
    python3 bench/compile_time.py 6 10 14 --lengths --repo /tmp/old   # against another checkout
    python3 bench/compile_time.py 6 10 14 --prismatic   # every second joint prismatic
    python3 bench/compile_time.py 6 7 --spatial         # #[derive(SpatialArm)]: PUMA 560, Panda
"""

import argparse
import os
import re
import subprocess
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def crate(root, n, params, lengths=False, repo=REPO, derivatives=False, prismatic=False):
    name = (
        f"arm{n}{'p' if params else ''}{'l' if lengths else ''}{'d' if derivatives else ''}"
        f"{'s' if prismatic else ''}"
    )
    path = os.path.join(root, name)
    os.makedirs(os.path.join(path, "src"), exist_ok=True)
    with open(os.path.join(path, "Cargo.toml"), "w") as f:
        f.write(
            f'[package]\nname = "{name}"\nversion = "0.0.0"\nedition = "2021"\n'
            f'[dependencies]\nplanar_arm = {{ path = "{repo}" }}\n[workspace]\n'
        )
    links, fields, values = [], [], []
    for i in range(n):
        kind = "Prismatic" if prismatic and i % 2 == 1 else "Revolute"
        length = f"{i % 3 + 2}/4"
        if lengths:
            length = f"self.len{i}"
            fields.append(f"    len{i}: f64,")
            values.append(f"len{i}: {i % 3 + 2}.0 / 4.0,")
        if params:
            links.append(
                f"    #[arm(length = {length}, mass = self.m{i}, inertia = self.i{i}, com = self.c{i})]\n"
                f"    l{i}: {kind},"
            )
            fields.append(f"    m{i}: f64,\n    i{i}: f64,\n    c{i}: f64,")
            values.append(f"m{i}: {i % 4 + 1}.0 / 2.0, i{i}: 1.0 / {i + 5}.0, c{i}: {i % 3 + 1}.0 / 5.0,")
        else:
            links.append(
                f"    #[arm(length = {length}, mass = {i % 4 + 1}/2, inertia = 1/{i + 5}, com = {i % 3 + 1}/5)]\n"
                f"    l{i}: {kind},"
            )
        values.append(f"l{i}: {kind},")
    body = "\n".join(links + fields)
    init = " ".join(values)
    with open(os.path.join(path, "src", "main.rs"), "w") as f:
        f.write(
            "use planar_arm::prelude::*;\n\n"
            "#[derive(PlanarArm)]\n#[arm(gravity = 9.81)]\n"
            f"struct Arm {{\n{body}\n}}\n\n"
            "fn main() {\n"
            f"    let arm = Arm {{ {init} }};\n"
            f"    let q = SVector::<f64, {n}>::from_fn(|i, _| 0.1 * i as f64);\n"
            "    let tau = arm.inverse_dynamics(&q, &q, &q);\n"
            "    let qdd = arm.forward_dynamics(&q, &q, &tau);\n"
            "    let (m, h) = (arm.mass_matrix(&q), arm.bias(&q, &q));\n"
            + (
                "    let (a, _b) = arm.linearize(&q, &q, &tau);\n"
                '    println!("{}", a.norm());\n'
                if derivatives
                else ""
            )
            + '    println!("{}", (qdd - q).norm() + m.norm() + h.norm());\n'
            "}\n"
        )
    return name, path


def spatial_crate(root, n, params, repo=REPO, derivatives=False, exact=False):
    """A crate deriving an `n`-joint spatial arm: the PUMA 560 at six joints, Franka's Panda
    (modified DH) at seven, otherwise a chain of alternating twists; with `params` its masses
    and centres of mass are run-time parameters; with `exact`, `#[arm(exact_dynamics)]`. It calls
    the kinematics, the closed-form IK, and the inverse and forward dynamics, mass matrix and
    bias, so that those are compiled."""
    name = f"spatial{n}{'p' if params else ''}{'d' if derivatives else ''}{'x' if exact else ''}"
    path = os.path.join(root, name)
    os.makedirs(os.path.join(path, "src"), exist_ok=True)
    with open(os.path.join(path, "Cargo.toml"), "w") as f:
        f.write(
            f'[package]\nname = "{name}"\nversion = "0.0.0"\nedition = "2021"\n'
            f'[dependencies]\nplanar_arm = {{ path = "{repo}" }}\n[workspace]\n'
        )
    puma = [
        "dh(a = 0, alpha = pi/2, d = 0)", "dh(a = 0.4318, alpha = 0, d = 0)",
        "dh(a = 0.0203, alpha = -pi/2, d = 0.15005)", "dh(a = 0, alpha = pi/2, d = 0.4318)",
        "dh(a = 0, alpha = -pi/2, d = 0)", "dh(a = 0, alpha = 0, d = 0)",
    ]
    panda = [
        "mdh(a = 0, alpha = 0, d = 0.333)", "mdh(a = 0, alpha = -pi/2, d = 0)",
        "mdh(a = 0, alpha = pi/2, d = 0.316)", "mdh(a = 0.0825, alpha = pi/2, d = 0)",
        "mdh(a = -0.0825, alpha = -pi/2, d = 0.384)", "mdh(a = 0, alpha = pi/2, d = 0)",
        "mdh(a = 0.088, alpha = pi/2, d = 0)",
    ]
    geometry = puma if n == 6 else panda if n == 7 else [
        f"dh(a = {i % 3 + 1}/10, alpha = {'pi/2' if i % 2 == 0 else '-pi/2'}, d = {i % 2}/10)"
        for i in range(n)
    ]
    links, fields, values = [], [], []
    for i in range(n):
        mass = f"self.m{i}" if params else f"{i % 4 + 1}/2"
        com = f"(self.c{i}, 0, 0.05)" if params else f"({i % 3 + 1}/50, 0, 0.05)"
        if params:
            fields.append(f"    m{i}: f64,\n    c{i}: f64,")
            values.append(f"m{i}: 1.5, c{i}: 0.02,")
        links.append(
            f"    #[arm({geometry[i]}, mass = {mass}, com = {com}, inertia(xx = 0.01, yy = 0.02, zz = 0.015))]\n"
            f"    j{i}: Revolute,"
        )
        values.append(f"j{i}: Revolute,")
    with open(os.path.join(path, "src", "main.rs"), "w") as f:
        f.write(
            "use planar_arm::prelude::*;\n\n"
            "#[derive(SpatialArm)]\n"
            f"#[arm(gravity = (0, 0, -9.81){', exact_dynamics' if exact else ''})]\n"
            f"struct Arm {{\n{chr(10).join(links + fields)}\n}}\n\n"
            "fn main() {\n"
            f"    let arm = Arm {{ {' '.join(values)} }};\n"
            f"    let q = SVector::<f64, {n}>::from_fn(|i, _| 0.1 * i as f64);\n"
            "    let pose = arm.tip_pose(&q);\n"
            "    let j = arm.jacobian(&q);\n"
            "    let g = arm.gravity(&q);\n"
            "    let ik = arm.inverse_kinematics(&pose).map_or(0, |s| s.len());\n"
            "    let tau = arm.inverse_dynamics(&q, &q, &q);\n"
            "    let qdd = arm.forward_dynamics(&q, &q, &tau);\n"
            "    let m = arm.mass_matrix(&q);\n"
            "    let h = arm.bias(&q, &q);\n"
            '    println!("{} {} {} {ik}", pose.translation.vector.norm(), j.norm(), g.norm());\n'
            '    println!("{} {} {} {}", tau.norm(), qdd.norm(), m.norm(), h.norm());\n'
            + (
                "    let (dq, dqd) = arm.inverse_dynamics_derivatives(&q, &q, &q);\n"
                '    println!("{} {}", dq.norm(), dqd.norm());\n'
                if derivatives
                else ""
            )
            + "}\n"
        )
    return name, path


def timed_build(path, name, target):
    env = dict(os.environ, CARGO_TARGET_DIR=target)
    env.pop("RUSTFLAGS", None)
    subprocess.run(["cargo", "clean", "-q", "-p", name], cwd=path, env=env, check=True)
    out = subprocess.run(
        ["/usr/bin/time", "-f", "%e %M", "cargo", "build", "-q"],
        cwd=path, env=env, capture_output=True, text=True, check=True,
    )
    seconds, kb = re.findall(r"([\d.]+) (\d+)\s*$", out.stderr)[-1]
    return float(seconds), int(kb) / 1024


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sizes", nargs="*", type=int, default=[6, 10, 14, 20, 30])
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--literal-only", action="store_true")
    ap.add_argument("--lengths", action="store_true", help="run-time lengths in the parameterised arms")
    ap.add_argument("--repo", default=REPO, help="the planar_arm checkout to build against")
    ap.add_argument(
        "--derivatives", action="store_true",
        help="also call linearize (so the derivatives are compiled, not only type-checked)",
    )
    ap.add_argument(
        "--spatial", action="store_true",
        help="#[derive(SpatialArm)] of n joints (the PUMA 560 at six, the Panda at seven)",
    )
    ap.add_argument(
        "--exact-dynamics", action="store_true",
        help="with --spatial: #[arm(exact_dynamics)] (M and c multiplied out for EXACT)",
    )
    ap.add_argument(
        "--prismatic", action="store_true",
        help="every second joint prismatic (links 2, 4, ...)",
    )
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as root:
        target = os.path.join(root, "target")
        print("| links | arm | clean rebuild s | peak MB |")
        print("|---|---|---|---|")
        for n in args.sizes:
            kinds = [False] if args.literal_only or n > 14 else [False, True]
            for params in kinds:
                if args.spatial:
                    name, path = spatial_crate(
                        root, n, params, args.repo, args.derivatives, args.exact_dynamics
                    )
                else:
                    name, path = crate(
                        root, n, params, args.lengths and params, args.repo, args.derivatives,
                        args.prismatic,
                    )
                env = dict(os.environ, CARGO_TARGET_DIR=target)
                subprocess.run(["cargo", "build", "-q"], cwd=path, env=env, check=True)
                best = min(timed_build(path, name, target) for _ in range(args.runs))
                kind = ("parameters, lengths" if args.lengths else "parameters") if params else "literal"
                if args.spatial:
                    kind = "spatial, " + kind
                if args.exact_dynamics:
                    kind += ", exact_dynamics"
                if args.prismatic:
                    kind += ", every second joint prismatic"
                print(f"| {n} | {kind} | {best[0]:.2f} | {best[1]:.0f} |", flush=True)


if __name__ == "__main__":
    main()
