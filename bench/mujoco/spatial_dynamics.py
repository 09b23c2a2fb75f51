"""MuJoCo's mass matrix, bias forces, passive damping, inverse and forward dynamics of two
spatial arms, written as the fixture tests/data/mujoco_spatial_dynamics.txt that
tests/spatial_dynamics_mujoco.rs reads.

Run by hand (CI does not install MuJoCo):

    python3 -m venv /tmp/mujoco_venv && /tmp/mujoco_venv/bin/pip install mujoco numpy
    /tmp/mujoco_venv/bin/python bench/mujoco/spatial_dynamics.py \
        > tests/data/mujoco_spatial_dynamics.txt

The arms: the PUMA 560 of examples/support/puma_arm.rs (Corke's standard DH parameters and
mass properties) with armature and damping on its first three joints, and a seven-joint arm
in Craig's modified DH with theta offsets, random full inertia tensors, centres of mass off
every axis, armature, damping and a random gravity (seeded, so the file is reproducible).

Each arm is an MJCF string built here. Every MuJoCo body frame is the arm's link frame, so
each <inertial> is the link's centre of mass and tensor as they are written:

- modified DH, T_i = Rx(alpha) Tx(a) Rz(theta + q) Tz(d): body i sits at
  Rx(alpha) Tx(a) Rz(theta) Tz(d) in body i-1, its hinge through its own origin along z;
- standard DH, T_i = Rz(theta + q) Tz(d) Tx(a) Rx(alpha): link frame i is at the link's
  distal end, and joint i turns about z_(i-1). Body i sits at Rz(theta) Tz(d) Tx(a) Rx(alpha)
  in body i-1 and its hinge, in its own frame, is the line through (-a, 0, 0) along
  (0, sin alpha, cos alpha), which is z_(i-1) seen from frame i. A MuJoCo hinge turns its body
  about that line, so the body's pose at q is Rz(q) Rz(theta) Tz(d) Tx(a) Rx(alpha), T_i(q).

Corke's PUMA is not physical: link 1 has no mass and moments (0, 0.35, 0), link 3's moments
(0.066, 0.086, 0.0125) break the triangle inequality, and MuJoCo's compiler refuses both. The
MJCF carries Corke's values and compiles with balanceinertia and boundmass, which replace them;
the script then writes Corke's values back into mjModel (body_mass, body_inertia with body_iquat
the identity, body_subtreemass), which the run-time dynamics use as they are. Every other
body's compiled mass properties are checked to be the ones written.

Frictionloss is zero (MuJoCo makes it a constraint, the crate a force); contacts and
constraints are disabled; the integrator is RK4, so mj_forward's qacc has no implicit damping.
"""

import sys

import mujoco
import numpy as np

H = np.pi / 2


def exact(v):
    # The derive's cosines and sines of multiples of pi/2 are exact.
    r = round(v)
    return float(r) if abs(v - r) < 1e-15 else float(v)


def rot_x(alpha):
    c, s = exact(np.cos(alpha)), exact(np.sin(alpha))
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_z(theta):
    c, s = exact(np.cos(theta)), exact(np.sin(theta))
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def quat(rotation):
    q = np.zeros(4)
    mujoco.mju_mat2Quat(q, rotation.flatten())
    return q


def fmt(values):
    return " ".join(repr(float(v)) for v in values)


def mjcf(name, convention, rows, links, armature, damping, gravity):
    """rows: (a, alpha, d, theta); links: (mass, com, 3x3 inertia about the com)."""
    body = []
    for k, ((a, alpha, d, theta), (mass, com, inertia)) in enumerate(zip(rows, links)):
        if convention == "mdh":
            pos = rot_x(alpha) @ np.array([a, 0.0, d])
            rotation = rot_x(alpha) @ rot_z(theta)
            anchor, axis = np.zeros(3), np.array([0.0, 0.0, 1.0])
        else:
            pos = rot_z(theta) @ np.array([a, 0.0, d])
            rotation = rot_z(theta) @ rot_x(alpha)
            anchor = np.array([-a, 0.0, 0.0])
            axis = np.array([0.0, exact(np.sin(alpha)), exact(np.cos(alpha))])
        i = np.array(inertia)
        if np.count_nonzero(i - np.diag(np.diag(i))) == 0:
            spec = f'diaginertia="{fmt(np.diag(i))}"'
        else:
            spec = f'fullinertia="{fmt([i[0, 0], i[1, 1], i[2, 2], i[0, 1], i[0, 2], i[1, 2]])}"'
        body.append(
            f'<body name="link{k + 1}" pos="{fmt(pos)}" quat="{fmt(quat(rotation))}">'
            f'<joint name="joint{k + 1}" type="hinge" pos="{fmt(anchor)}" axis="{fmt(axis)}" '
            f'armature="{float(armature[k])!r}" damping="{float(damping[k])!r}" frictionloss="0"/>'
            f'<inertial pos="{fmt(com)}" mass="{float(mass)!r}" {spec}/>'
        )
    return (
        f'<mujoco model="{name}">'
        '<compiler angle="radian" balanceinertia="true" boundmass="1e-9"/>'
        f'<option gravity="{fmt(gravity)}" integrator="RK4" timestep="0.001">'
        '<flag contact="disable" constraint="disable"/></option>'
        "<worldbody>" + "".join(body) + "</body>" * len(body) + "</worldbody></mujoco>"
    )


def restore(model, links):
    """Writes each link's mass properties back where the compiler changed them."""
    for k, (mass, com, inertia) in enumerate(links):
        b = k + 1
        assert np.array_equal(model.body_ipos[b], com), (b, model.body_ipos[b])
        i = np.array(inertia)
        diagonal = np.count_nonzero(i - np.diag(np.diag(i))) == 0
        if diagonal and (model.body_mass[b] != mass or not np.array_equal(model.body_inertia[b], np.diag(i))):
            print(f"# {model.body(b).name}: compiled mass {float(model.body_mass[b])!r}, moments "
                  f"{model.body_inertia[b]}; written back {mass!r}, {np.diag(i)}", file=sys.stderr)
            model.body_mass[b] = mass
            model.body_inertia[b] = np.diag(i)
            model.body_iquat[b] = [1.0, 0.0, 0.0, 0.0]
        else:
            assert model.body_mass[b] == mass
            # The compiler's eigen-decomposition of a full tensor, put back together.
            r = np.zeros(9)
            mujoco.mju_quat2Mat(r, model.body_iquat[b])
            r = r.reshape(3, 3)
            back = r @ np.diag(model.body_inertia[b]) @ r.T
            gap = np.abs(back - i).max() / np.abs(i).max()
            print(f"# {model.body(b).name}: compiled tensor within {gap:.1e} of the written one", file=sys.stderr)
    for b in range(model.nbody - 1, 0, -1):
        children = [c for c in range(model.nbody) if c != b and model.body_parentid[c] == b]
        model.body_subtreemass[b] = model.body_mass[b] + sum(model.body_subtreemass[c] for c in children)
    model.body_subtreemass[0] = model.body_subtreemass[1]


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
    armature = [0.2, 0.2, 0.1, 0.0, 0.0, 0.0]
    damping = [0.5, 0.5, 0.3, 0.0, 0.0, 0.0]
    return "Puma560", "dh", rows, links, armature, damping, [0.0, 0.0, -9.81]


def random_mdh(rng):
    rows, links = [], []
    for _ in range(7):
        rows.append((rng.uniform(-0.4, 0.4), rng.uniform(-3, 3), rng.uniform(-0.4, 0.4), rng.uniform(-3, 3)))
        principal = rng.uniform(0.01, 0.2, 3)
        moments = np.array([principal[1] + principal[2], principal[0] + principal[2], principal[0] + principal[1]])
        turn = np.zeros(9)
        q = rng.normal(size=4)
        mujoco.mju_quat2Mat(turn, q / np.linalg.norm(q))
        turn = turn.reshape(3, 3)
        inertia = turn @ np.diag(moments) @ turn.T
        links.append((rng.uniform(0.2, 3.0), list(rng.uniform(-0.3, 0.3, 3)), (inertia + inertia.T) / 2))
    armature = list(rng.uniform(0.0, 0.2, 7))
    damping = list(rng.uniform(0.0, 0.5, 7))
    gravity = list(rng.uniform(-10, 10, 3))
    return "Random7", "mdh", rows, links, armature, damping, gravity


def line(key, values):
    return key + " " + fmt(values)


FORMAT = """\
# Format: '#' lines are comments. Each arm starts with 'arm NAME CONVENTION N' (CONVENTION dh
# or mdh, every joint a hinge), then
#   gravity gx gy gz                    (m/s^2, base frame)
#   joint a alpha d theta armature damping         N lines, base first (frictionloss 0)
#   link mass cx cy cz ixx iyy izz ixy ixz iyz      N lines: the centre of mass in the link
#                                       frame, the tensor about it in the link's axes
# then states of ten lines each:
#   q, qd, qdd                          the state and the accelerations asked for
#   M                                   mj_fullM after mj_forward, row-major N*N
#                                       (armature on the diagonal)
#   bias                                qfrc_bias = c + g (no damping)
#   gravity_torque                      qfrc_bias at qd = 0, g alone
#   passive                             qfrc_passive = -damping qd
#   tau                                 qfrc_inverse of mj_inverse at (q, qd, qdd):
#                                       M qdd + c + g + damping qd
#   applied                             a qfrc_applied, no other force
#   qacc                                mj_forward's qacc at (q, qd) under 'applied'
"""


def main():
    rng = np.random.default_rng(20261206)
    print("# Written by bench/mujoco/spatial_dynamics.py with mujoco", mujoco.__version__)
    print(FORMAT, end="")
    for name, convention, rows, links, armature, damping, gravity in [puma(), random_mdh(rng)]:
        xml = mjcf(name, convention, rows, links, armature, damping, gravity)
        model = mujoco.MjModel.from_xml_string(xml)
        restore(model, links)
        data = mujoco.MjData(model)
        n = len(rows)
        assert model.nv == n
        print(f"arm {name} {convention} {n}")
        print(line("gravity", gravity))
        for row, arm, damp in zip(rows, armature, damping):
            print(line("joint", list(row) + [arm, damp]))
        for mass, com, inertia in links:
            i = np.array(inertia)
            print(line("link", [mass] + list(com) + [i[0, 0], i[1, 1], i[2, 2], i[0, 1], i[0, 2], i[1, 2]]))
        worst = 0.0
        for _ in range(6):
            q, qd, qdd = rng.uniform(-3, 3, n), rng.uniform(-2, 2, n), rng.uniform(-5, 5, n)
            data.qpos[:], data.qvel[:], data.qfrc_applied[:] = q, qd, 0.0
            mujoco.mj_forward(model, data)
            mass = np.zeros((n, n))
            mujoco.mj_fullM(model, data, mass)
            bias, passive = data.qfrc_bias.copy(), data.qfrc_passive.copy()
            data.qacc[:] = qdd
            mujoco.mj_inverse(model, data)
            tau = data.qfrc_inverse.copy()
            worst = max(worst, np.abs(tau - (mass @ qdd + bias - passive)).max() / max(1.0, np.abs(tau).max()))
            data.qvel[:] = 0.0
            mujoco.mj_forward(model, data)
            still = data.qfrc_bias.copy()
            applied = bias - passive + np.diag(mass) * rng.uniform(-5, 5, n)
            data.qvel[:], data.qfrc_applied[:] = qd, applied
            mujoco.mj_forward(model, data)
            qacc = data.qacc.copy()
            for key, values in [("q", q), ("qd", qd), ("qdd", qdd), ("M", mass.flatten()), ("bias", bias),
                                ("gravity_torque", still), ("passive", passive), ("tau", tau),
                                ("applied", applied), ("qacc", qacc)]:
                print(line(key, values))
        print(f"# {name}: qfrc_inverse against M qdd + qfrc_bias - qfrc_passive: {worst:.1e}", file=sys.stderr)


if __name__ == "__main__":
    main()
