"""The UR5 and Franka Panda of ARMS=spatial-dynamics, read from example-robot-data's URDFs.

Run by hand with the venv of run.sh (`pip install example-robot-data` into it):

    /tmp/pinocchio_bench/venv/bin/python bench/pinocchio/urdf_arms.py

It prints, per arm and joint, the URDF joint origin (xyz, rpy), axis and the link's mass,
centre of mass and inertia about it in the link frame, with every fixed joint's massive child
merged into its moving parent (the Panda's hand and its two fingers, at zero opening, into
link 7) by the parallel-axis theorem in numpy. These are the numbers written into
benches/spatial_dynamics.rs and peers.cpp. It checks them against Pinocchio's own URDF
parser (buildModelFromUrdf, then buildReducedModel locking the fingers at 0): the joint
placements and the merged inertias must agree to 1e-12, or it stops.
"""

import math
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pinocchio as pin

ROBOTS = Path(pin.__file__).resolve()
for up in ROBOTS.parents:
    if (up / "cmeel.prefix").is_dir():
        ROBOTS = up / "cmeel.prefix/share/example-robot-data/robots"
        break


def floats(s, default="0 0 0"):
    return np.array([float(x) for x in (s or default).split()])


def rpy_matrix(rpy):
    return pin.rpy.rpyToMatrix(*rpy)


def link_inertial(link):
    """(mass, com, inertia about com in the link's axes) of a URDF <link>, or None."""
    i = link.find("inertial")
    if i is None:
        return None
    origin = i.find("origin")
    xyz = floats(origin.get("xyz") if origin is not None else None)
    rpy = floats(origin.get("rpy") if origin is not None else None)
    m = float(i.find("mass").get("value"))
    t = i.find("inertia")
    g = {k: float(t.get(k, "0")) for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")}
    tensor = np.array(
        [[g["ixx"], g["ixy"], g["ixz"]], [g["ixy"], g["iyy"], g["iyz"]], [g["ixz"], g["iyz"], g["izz"]]]
    )
    r = rpy_matrix(rpy)
    return m, xyz, r @ tensor @ r.T


def merge(bodies):
    """Bodies (mass, com, inertia about com), all in one frame: their sum about its com (a
    single body as it is)."""
    if len(bodies) == 1:
        return bodies[0]
    mass = sum(m for m, _, _ in bodies)
    com = sum(m * c for m, c, _ in bodies) / mass
    inertia = np.zeros((3, 3))
    for m, c, i in bodies:
        d = c - com
        inertia += i + m * (d @ d * np.eye(3) - np.outer(d, d))
    return mass, com, inertia


def chain(urdf, moving, lock=()):
    """The moving joints' (name, xyz, rpy, axis) and each one's link with everything fixed
    (or locked at 0) below it merged, as (mass, com, inertia) in the link frame."""
    root = ET.parse(urdf).getroot()
    links = {l.get("name"): l for l in root.findall("link")}
    joints = root.findall("joint")
    children = {}
    for j in joints:
        children.setdefault(j.find("parent").get("link"), []).append(j)
    out = []
    for name in moving:
        j = next(j for j in joints if j.get("name") == name)
        o = j.find("origin")
        xyz, rpy = floats(o.get("xyz")), floats(o.get("rpy"))
        axis = floats(j.find("axis").get("xyz"))
        # The link, then everything hanging from it by fixed (or locked) joints.
        bodies = []
        stack = [(j.find("child").get("link"), np.eye(3), np.zeros(3))]
        while stack:
            lname, r, p = stack.pop()
            inertial = link_inertial(links[lname])
            if inertial is not None and inertial[0] > 0:
                m, c, i = inertial
                bodies.append((m, r @ c + p, r @ i @ r.T))
            for cj in children.get(lname, []):
                if cj.get("type") == "fixed" or cj.get("name") in lock:
                    co = cj.find("origin")
                    cr = rpy_matrix(floats(co.get("rpy") if co is not None else None))
                    cp = floats(co.get("xyz") if co is not None else None)
                    stack.append((cj.find("child").get("link"), r @ cr, r @ cp + p))
        out.append((name, xyz, rpy, axis, merge(bodies)))
    return out


def check(urdf, arm, lock=()):
    model = pin.buildModelFromUrdf(str(urdf))
    if lock:
        model = pin.buildReducedModel(model, [model.getJointId(n) for n in lock], pin.neutral(model))
    worst = 0.0
    for k, (name, xyz, rpy, axis, (m, c, i)) in enumerate(arm, start=1):
        assert model.names[k] == name, (model.names[k], name)
        placement = model.jointPlacements[k]
        worst = max(worst, np.abs(placement.translation - xyz).max())
        worst = max(worst, np.abs(placement.rotation - rpy_matrix(rpy)).max())
        y = model.inertias[k]
        worst = max(worst, abs(y.mass - m), np.abs(y.lever - c).max(), np.abs(y.inertia - i).max())
    print(f"# {urdf.name}: numpy merge vs Pinocchio's URDF parser, largest difference {worst:.1e}")
    if worst > 1e-12:
        sys.exit("the URDF numbers and Pinocchio's model disagree")


def num(x):
    """A number as written in the attributes: the shortest decimal that reads back to it."""
    x = float(x)
    return str(int(x)) if x == int(x) else repr(x)


def angle(x):
    """URDF's 1.5707963267948966 (the Panda) and 1.57079632679 (the UR5) are a quarter turn,
    written `pi/2` (the derive's cosine and sine of it are exact, and so are peers.cpp's)."""
    if abs(abs(x) - math.pi / 2) < 1e-10:
        return ("-" if x < 0 else "") + "pi/2"
    return num(x)


def show(name, arm):
    """The arm as #[arm(...)] attributes for benches/spatial_dynamics.rs and as peers.cpp's
    UrdfLink initialisers."""
    print(f"\n// {name}: Rust")
    for jname, xyz, rpy, axis, (m, c, i) in arm:
        t = lambda v: "(" + ", ".join(num(x) for x in v) + ")"
        r = "(" + ", ".join(angle(x) for x in rpy) + ")"
        print(
            f"    #[arm(origin(xyz = {t(xyz)}, rpy = {r}), axis = {t(axis)},\n"
            f"          mass = {num(m)}, com = {t(c)},\n"
            f"          inertia(xx = {num(i[0,0])}, yy = {num(i[1,1])}, zz = {num(i[2,2])}, "
            f"xy = {num(i[0,1])}, xz = {num(i[0,2])}, yz = {num(i[1,2])}))]\n    {jname}: Revolute,"
        )
    print(f"\n// {name}: C++")
    for jname, xyz, rpy, axis, (m, c, i) in arm:
        ax = "xyz"[int(np.argmax(np.abs(axis)))]
        assert np.abs(axis).sum() == 1 and axis.max() == 1, "axis along +x, +y or +z"
        t = lambda v: "{" + ", ".join(num(x) for x in v) + "}"
        r = "{" + ", ".join(angle(x).replace("pi/2", "H") for x in rpy) + "}"
        print(
            f"     {{{t(xyz)}, {r}, '{ax}', {num(m)}, {t(c)},\n"
            f"      {{{num(i[0,0])}, {num(i[1,1])}, {num(i[2,2])}, {num(i[0,1])}, {num(i[0,2])}, {num(i[1,2])}}}}},"
        )


def main():
    ur5 = ROBOTS / "ur_description/urdf/ur5_robot.urdf"
    panda = ROBOTS / "panda_description/urdf/panda.urdf"
    ur5_joints = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
                  "wrist_2_joint", "wrist_3_joint"]
    panda_joints = [f"panda_joint{k}" for k in range(1, 8)]
    fingers = ("panda_finger_joint1", "panda_finger_joint2")
    a = chain(ur5, ur5_joints)
    b = chain(panda, panda_joints, fingers)
    check(ur5, a)
    check(panda, b, fingers)
    show(f"UR5 ({ur5})", a)
    show(f"Panda ({panda}), hand and fingers merged into link 7", b)


if __name__ == "__main__":
    main()
