"""Pinocchio's inverse dynamics and mass matrix of two spatial arms, written as the fixture
tests/data/pinocchio_spatial_dynamics.txt that tests/spatial_dynamics_reference.rs reads.

Run by hand (CI does not install Pinocchio), with the venv bench/pinocchio/run.sh makes:

    /tmp/pinocchio_bench/venv/bin/python bench/pinocchio/spatial_dynamics.py \
        > tests/data/pinocchio_spatial_dynamics.txt

The arms: the PUMA 560 of examples/puma.rs (Corke's standard DH and mass properties) and a
seven-joint arm in Craig's modified DH with theta offsets, random full inertia tensors,
centres of mass off every axis and armature (seeded, so the file is reproducible). Each joint
is a JointModelRZ placed by the constant part of the DH transforms (as peers.cpp builds them),
each body's inertia placed in its joint's frame by what separates the link frame from it.
"""

import numpy as np
import pinocchio as pin

H = np.pi / 2


def rot_x(alpha):
    c, s = np.cos(alpha), np.sin(alpha)
    # The derive's cosines and sines of multiples of pi/2 are exact.
    c, s = (round(c) if abs(c - round(c)) < 1e-15 else c), (round(s) if abs(s - round(s)) < 1e-15 else s)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_z(theta):
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def build(convention, rows, links, armature, gravity):
    """rows: (a, alpha, d, theta); links: (mass, com, 3x3 inertia about the com)."""
    model = pin.Model()
    model.gravity.linear = np.array(gravity)
    carry = pin.SE3.Identity()
    parent = 0
    for k, ((a, alpha, d, theta), (mass, com, inertia)) in enumerate(zip(rows, links)):
        if convention == "mdh":
            # T_i = Rx(alpha) Tx(a) Rz(theta + q) Tz(d); link frame i = joint frame Tz(d).
            placement = carry * pin.SE3(rot_x(alpha), np.array([a, 0.0, 0.0])) * pin.SE3(rot_z(theta), np.zeros(3))
            body = pin.SE3(np.eye(3), np.array([0.0, 0.0, d]))
        else:
            # T_i = Rz(theta + q) Tz(d) Tx(a) Rx(alpha); link frame i = joint frame B_i.
            placement = carry * pin.SE3(rot_z(theta), np.zeros(3))
            body = pin.SE3(rot_x(alpha), np.array([a, 0.0, d]))
        parent = model.addJoint(parent, pin.JointModelRZ(), placement, f"joint{k + 1}")
        model.appendBodyToJoint(parent, pin.Inertia(mass, np.array(com), np.array(inertia)), body)
        carry = body
    model.armature = np.array(armature)
    return model


def tensor(xx, yy, zz, xy=0.0, xz=0.0, yz=0.0):
    return [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]


def puma():
    rows = [(0, H, 0, 0), (0.4318, 0, 0, 0), (0.0203, -H, 0.15005, 0), (0, H, 0.4318, 0), (0, -H, 0, 0), (0, 0, 0, 0)]
    links = [
        (0.0, [0, 0, 0], tensor(0, 0.35, 0)),
        (17.4, [-0.3638, 0.006, 0.2275], tensor(0.13, 0.524, 0.539)),
        (4.8, [-0.0203, -0.0141, 0.07], tensor(0.066, 0.086, 0.0125)),
        (0.82, [0, 0.019, 0], tensor(1.8e-3, 1.3e-3, 1.8e-3)),
        (0.34, [0, 0, 0], tensor(0.3e-3, 0.4e-3, 0.3e-3)),
        (0.09, [0, 0, 0.032], tensor(0.15e-3, 0.15e-3, 0.04e-3)),
    ]
    return "Puma560", "dh", rows, links, [0.0] * 6, [0.0, 0.0, -9.81]


def random_mdh(rng):
    rows, links = [], []
    for _ in range(7):
        rows.append((rng.uniform(-0.4, 0.4), rng.uniform(-3, 3), rng.uniform(-0.4, 0.4), rng.uniform(-3, 3)))
        principal = rng.uniform(0.01, 0.2, 3)
        moments = np.array([principal[1] + principal[2], principal[0] + principal[2], principal[0] + principal[1]])
        turn = pin.rpy.rpyToMatrix(*rng.uniform(-3, 3, 3))
        inertia = turn @ np.diag(moments) @ turn.T
        links.append((rng.uniform(0.2, 3.0), list(rng.uniform(-0.3, 0.3, 3)), (inertia + inertia.T) / 2))
    armature = list(rng.uniform(0.0, 0.2, 7))
    gravity = list(rng.uniform(-10, 10, 3))
    return "Random7", "mdh", rows, links, armature, gravity


def line(key, values):
    return key + " " + " ".join(repr(float(v)) for v in values)


def main():
    rng = np.random.default_rng(20261205)
    print("# Written by bench/pinocchio/spatial_dynamics.py with pin", pin.__version__)
    for name, convention, rows, links, armature, gravity in [puma(), random_mdh(rng)]:
        model = build(convention, rows, links, armature, gravity)
        data = model.createData()
        n = len(rows)
        print(f"arm {name} {convention} {n}")
        print(line("gravity", gravity))
        for row, arm in zip(rows, armature):
            print(line("joint", list(row) + [arm]))
        for mass, com, inertia in links:
            i = np.array(inertia)
            print(line("link", [mass] + list(com) + [i[0, 0], i[1, 1], i[2, 2], i[0, 1], i[0, 2], i[1, 2]]))
        for _ in range(5):
            q, qd, qdd = rng.uniform(-3, 3, n), rng.uniform(-2, 2, n), rng.uniform(-5, 5, n)
            tau = pin.rnea(model, data, q, qd, qdd)
            mass = pin.crba(model, data, q)
            mass = np.triu(mass) + np.triu(mass, 1).T
            print(line("q", q))
            print(line("qd", qd))
            print(line("qdd", qdd))
            print(line("tau", tau))
            print(line("M", mass.flatten()))


if __name__ == "__main__":
    main()
