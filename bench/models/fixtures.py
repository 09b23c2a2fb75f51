"""Reference joint-space dynamics of the model files in models/, from MuJoCo and Pinocchio,
written as the fixture tests/data/models_peers.txt.

Run by hand (CI installs neither MuJoCo nor Pinocchio), from the repository root:

    python3 bench/models/fixtures.py > tests/data/models_peers.txt

It needs numpy, `mujoco` and `pin` (Pinocchio) from PyPI. The checked-in file was produced
with Python 3.11.7, mujoco 4.0.1, pin (Pinocchio) 4.1.0 and numpy 2.4.6; the versions are
also written into the file's first comment lines.

Arms:

- MuJoCo (MJCF from dm_control): acrobot, cartpole, pendulum, reacher, hopper, swimmer6.
  Each model is loaded with mujoco.MjModel.from_xml_path, then constraints and contacts are
  disabled and fluid forces are switched off (opt.density = opt.viscosity = 0). The arm is
  the chain of joints from the world to the arm's tip body (TIPS below). Every other joint,
  if there is one, is held at qpos 0 and qvel 0 and its rows and columns are not written.
  A chain with a free or ball joint is skipped, and the script says so on stderr.
  M is mj_fullM, so dof_armature is on its diagonal. bias is qfrc_bias, which has no
  passive forces. gravity_torque is qfrc_bias at qvel = 0. damping is dof_damping. tau is
  qfrc_inverse of mj_inverse at (q, qd, qdd).
- Pinocchio (URDF from example-robot-data): ur5 (buildModelFromUrdf, 6 joints) and panda
  (buildReducedModel, with panda_finger_joint1 and panda_finger_joint2 locked at 0, 7 joints).
  M is crba with its upper triangle copied to the lower one. bias is nonLinearEffects.
  gravity_torque is computeGeneralizedGravity. damping is model.damping. tau is
  rnea(q, qd, qdd) + damping * qd.

Three random states per arm come from numpy.random.default_rng(SEED), one generator used
by all arms in the order written. q is uniform in [-1, 1] (slides: [-0.3, 0.3]), and qd and
qdd are uniform in [-1, 1].

Checks made before anything is written, stopping on failure: M is symmetric and positive
definite; MuJoCo's qfrc_inverse = M qdd + qfrc_bias - qfrc_passive and qfrc_passive =
-damping qd (to 1e-10); Pinocchio's rnea = M qdd + nle (to 1e-10) and crba's M equals the columns
rnea(q, 0, e_i) without gravity; bias at qd = 0 equals gravity_torque. Joints with stiffness, armature or frictionloss other than zero are listed,
together with the largest differences found, on stderr and in the file's comments.
"""

import platform
import sys
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin

ROOT = Path(__file__).resolve().parents[2]
MODELS = ROOT / "models"
SEED = 20240611
STATES = 3
TOL = 1e-10

# MuJoCo arm name -> (file, tip body). The chain is the joints on the path world -> tip.
MUJOCO_ARMS = [
    ("acrobot", "acrobot.xml", "lower_arm"),
    ("cartpole", "cartpole.xml", "pole_1"),
    ("pendulum", "pendulum.xml", "pole"),
    ("reacher", "reacher.xml", "finger"),
    ("hopper", "hopper.xml", "foot"),
    ("swimmer6", "swimmer6.xml", "segment_4"),
]

PANDA_LOCKED = ("panda_finger_joint1", "panda_finger_joint2")


def log(*args):
    print(*args, file=sys.stderr, flush=True)


def fmt(x):
    # repr of a Python float is the shortest string that reads back to the same double
    # (at most 17 significant digits).
    return repr(float(x))


def line(key, values):
    return key + " " + " ".join(fmt(v) for v in np.asarray(values, dtype=float).ravel())


def check_spd(name, M):
    asym = float(np.max(np.abs(M - M.T)))
    if asym > TOL * max(1.0, float(np.max(np.abs(M)))):
        raise SystemExit(f"{name}: M not symmetric ({asym})")
    eig = np.linalg.eigvalsh(0.5 * (M + M.T))
    if eig[0] <= 0:
        raise SystemExit(f"{name}: M not positive definite (eigenvalues {eig})")
    return asym, float(eig[0])


def random_state(rng, slide):
    n = len(slide)
    q = rng.uniform(-1.0, 1.0, n)
    q[slide] = rng.uniform(-0.3, 0.3, int(np.sum(slide)))
    qd = rng.uniform(-1.0, 1.0, n)
    qdd = rng.uniform(-1.0, 1.0, n)
    return q, qd, qdd


def evaluate(m, datas, dofs, qadr, q, qd, qdd):
    """The chain's joints at (q, qd, qdd), the others at rest: mj_forward into d (with qd) and
    dg (at rest, for gravity), mj_inverse into di (with qd and qdd)."""
    d, dg, di = datas
    for dd in datas:
        dd.qpos[:] = 0.0
        dd.qvel[:] = 0.0
        dd.qacc[:] = 0.0
        dd.qpos[qadr] = q
    d.qvel[dofs] = qd
    mujoco.mj_forward(m, d)
    mujoco.mj_forward(m, dg)  # qvel = 0
    di.qvel[dofs] = qd
    di.qacc[dofs] = qdd
    mujoco.mj_inverse(m, di)


def rigid_bodies_only(m):
    """Constraints, contacts and fluid forces off: what is left is the rigid-body dynamics with
    the joints' armature, damping and springs (frictionloss is a constraint in MuJoCo)."""
    m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)
    m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONTACT)
    m.opt.density = 0.0
    m.opt.viscosity = 0.0


def chain_joints(m, bodies):
    """The joints of these bodies, in qpos order."""
    joints = [j for b in bodies for j in range(m.body_jntadr[b], m.body_jntadr[b] + m.body_jntnum[b])]
    return sorted(joints, key=lambda j: m.jnt_qposadr[j])


def body_path(m, tip):
    """Bodies from the world's child down to tip (world excluded)."""
    b = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, tip)
    if b < 0:
        raise SystemExit(f"no body {tip}")
    path = []
    while b != 0:
        path.append(b)
        b = int(m.body_parentid[b])
    return path[::-1]


def mujoco_arm(name, file, tip, rng, notes, maxdiff, mineigs):
    m = mujoco.MjModel.from_xml_path(str(MODELS / file))
    rigid_bodies_only(m)

    path = body_path(m, tip)
    joints = chain_joints(m, path)
    jnames = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, j) for j in joints]
    types = [int(m.jnt_type[j]) for j in joints]
    if any(t in (int(mujoco.mjtJoint.mjJNT_FREE), int(mujoco.mjtJoint.mjJNT_BALL)) for t in types):
        log(f"{name}: skipped, a free or ball joint is on its chain")
        notes.append(f"{name}: skipped (free or ball joint on the chain)")
        return []
    others = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, j) for j in range(m.njnt) if j not in joints]

    # Tree shape along the chain: any body off the path, and bodies on it without a joint.
    children = {}
    for b in range(1, m.nbody):
        children.setdefault(int(m.body_parentid[b]), []).append(b)
    off_path = [b for b in range(1, m.nbody) if b not in path]
    branches = [
        mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b)
        for b in [0] + path
        if len(children.get(b, [])) > 1 or (b != path[-1] and len(children.get(b, [])) == 0)
    ]
    welded = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b) for b in path if m.body_jntnum[b] == 0]
    log(f"{name}: joints {jnames}; other joints {others}; bodies off the chain "
        f"{[mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b) for b in off_path]}; "
        f"bodies branching {branches}; chain bodies without a joint {welded}; "
        f"body_mass {[float(m.body_mass[b]) for b in path]}")

    dofs = np.array([m.jnt_dofadr[j] for j in joints])
    qadr = np.array([m.jnt_qposadr[j] for j in joints])
    slide = np.array([t == int(mujoco.mjtJoint.mjJNT_SLIDE) for t in types])
    for j, jn in zip(joints, jnames):
        d = m.jnt_dofadr[j]
        k, a, f = float(m.jnt_stiffness[j]), float(m.dof_armature[d]), float(m.dof_frictionloss[d])
        if k != 0 or a != 0 or f != 0:
            notes.append(f"{name}.{jn}: stiffness {fmt(k)} armature {fmt(a)} frictionloss {fmt(f)}")
        if k != 0:
            log(f"WARNING {name}.{jn}: stiffness {k} (spring force is in qfrc_passive and tau)")
    damping = m.dof_damping[dofs].copy()

    out = [f"arm {name}", "joints " + " ".join(jnames), line("gravity", m.opt.gravity)]
    d = mujoco.MjData(m)
    dg = mujoco.MjData(m)
    di = mujoco.MjData(m)
    Mfull = np.zeros((m.nv, m.nv))
    for _ in range(STATES):
        q, qd, qdd = random_state(rng, slide)
        evaluate(m, (d, dg, di), dofs, qadr, q, qd, qdd)

        mujoco.mj_fullM(m, d, Mfull)
        M = Mfull[np.ix_(dofs, dofs)].copy()
        bias = d.qfrc_bias[dofs].copy()
        grav = dg.qfrc_bias[dofs].copy()
        tau = di.qfrc_inverse[dofs].copy()
        passive = d.qfrc_passive[dofs].copy()

        asym, mineig = check_spd(name, M)
        mx = lambda a: float(np.max(np.abs(a)))
        diffs = {
            "M asymmetry": asym,
            "mj_inverse - (M qdd + bias - qfrc_passive)": mx(tau - (M @ qdd + bias - passive)),
            "qfrc_passive + damping qd": mx(passive + damping * qd),
            "mj_inverse - (M qdd + bias + damping qd)": mx(tau - (M @ qdd + bias + damping * qd)),
            "mj_inverse bias - mj_forward bias": mx(di.qfrc_bias[dofs] - bias),
        }
        rne = np.zeros(m.nv)
        mujoco.mj_rne(m, dg, 0, rne)
        diffs["gravity_torque - mj_rne(qd=0)"] = mx(rne[dofs] - grav)
        for k, v in diffs.items():
            if k != "M asymmetry" and v > TOL:
                raise SystemExit(f"{name}: {k} = {v}")
            maxdiff[k] = max(maxdiff.get(k, 0.0), v)
        mineigs[name] = min(mineigs.get(name, np.inf), mineig)

        out += [line("q", q), line("qd", qd), line("qdd", qdd), line("M", M), line("bias", bias),
                line("gravity_torque", grav), line("damping", damping), line("tau", tau)]
    return out


def pinocchio_arm(name, model, rng, notes, maxdiff, mineigs):
    if model.nq != model.nv:
        raise SystemExit(f"{name}: nq {model.nq} != nv {model.nv}")
    data = model.createData()
    jnames = list(model.names)[1:]
    slide = np.zeros(model.nv, dtype=bool)
    for i, j in enumerate(list(model.joints)[1:]):
        if j.nv != 1:
            raise SystemExit(f"{name}: joint {jnames[i]} has nv {j.nv}")
        s = j.shortname()
        slide[j.idx_v] = "Prismatic" in s or s.startswith("JointModelP")
    damping = np.array(model.damping, dtype=float)
    for i, jn in enumerate(jnames):
        a, f = float(model.armature[i]), float(model.friction[i])
        if a != 0 or f != 0:
            notes.append(f"{name}.{jn}: armature {fmt(a)} friction {fmt(f)}")
    log(f"{name}: joints {jnames}; damping {damping.tolist()}; armature {[float(a) for a in model.armature]}; "
        f"friction {[float(f) for f in model.friction]}; link masses {[float(i.mass) for i in list(model.inertias)[1:]]}")
    out = [f"arm {name}", "joints " + " ".join(jnames), line("gravity", model.gravity.linear)]
    for _ in range(STATES):
        q, qd, qdd = random_state(rng, slide)
        M = np.array(pin.crba(model, data, q))
        M = np.triu(M) + np.triu(M, 1).T
        # crba fills only the upper triangle; compare with the mass matrix rebuilt from rnea
        # (unit accelerations, qd = 0, no gravity) as an independent check of the symmetric M.
        g0 = model.gravity.linear.copy()
        model.gravity.linear[:] = 0.0
        Mcols = np.column_stack([pin.rnea(model, data, q, np.zeros(model.nv), e) for e in np.eye(model.nv)])
        model.gravity.linear[:] = g0
        asym_raw = float(np.max(np.abs(Mcols - M)))
        if asym_raw > TOL:
            raise SystemExit(f"{name}: crba vs rnea columns {asym_raw}")
        bias = np.array(pin.nonLinearEffects(model, data, q, qd))
        grav = np.array(pin.computeGeneralizedGravity(model, data, q))
        nle0 = np.array(pin.nonLinearEffects(model, data, q, np.zeros(model.nv)))
        rnea = np.array(pin.rnea(model, data, q, qd, qdd))
        tau = rnea + damping * qd

        asym, mineig = check_spd(name, M)
        mx = lambda a: float(np.max(np.abs(a)))
        diffs = {
            "rnea - (M qdd + nle)": mx(rnea - (M @ qdd + bias)),
            "computeGeneralizedGravity - nle(qd=0)": mx(grav - nle0),
        }
        for k, v in diffs.items():
            if v > TOL:
                raise SystemExit(f"{name}: {k} = {v}")
            maxdiff[k] = max(maxdiff.get(k, 0.0), v)
        maxdiff["crba M - rnea(q, 0, e_i) columns without gravity"] = max(
            maxdiff.get("crba M - rnea(q, 0, e_i) columns without gravity", 0.0), asym_raw)
        mineigs[name] = min(mineigs.get(name, np.inf), mineig)

        out += [line("q", q), line("qd", qd), line("qdd", qdd), line("M", M), line("bias", bias),
                line("gravity_torque", grav), line("damping", damping), line("tau", tau)]
    return out


def main():
    rng = np.random.default_rng(SEED)
    notes, maxdiff, mineigs, body = [], {}, {}, []
    for name, file, tip in MUJOCO_ARMS:
        body += mujoco_arm(name, file, tip, rng, notes, maxdiff, mineigs)

    ur5 = pin.buildModelFromUrdf(str(MODELS / "ur5.urdf"))
    body += pinocchio_arm("ur5", ur5, rng, notes, maxdiff, mineigs)

    panda_full = pin.buildModelFromUrdf(str(MODELS / "panda.urdf"))
    lock = [panda_full.getJointId(j) for j in PANDA_LOCKED]
    if any(i >= panda_full.njoints for i in lock):
        raise SystemExit("panda: finger joints not found")
    panda = pin.buildReducedModel(panda_full, lock, np.zeros(panda_full.nq))
    body += pinocchio_arm("panda", panda, rng, notes, maxdiff, mineigs)

    for k, v in maxdiff.items():
        log(f"max {k}: {v:.3e}")
    for k, v in mineigs.items():
        log(f"smallest eigenvalue of M, {k}: {v:.3e}")
    for n in notes:
        log("nonzero:", n)

    head = f"""\
# Written by bench/models/fixtures.py with Python {platform.python_version()}, mujoco {mujoco.__version__},
# pin (Pinocchio) {pin.__version__}, numpy {np.__version__}. numpy.random.default_rng({SEED}), {STATES} states per arm.
# Format: '#' lines are comments. Each arm starts with 'arm NAME', then
#   joints J1 J2 ...      the chain's joints (MuJoCo joint names in qpos order, or Pinocchio
#                         model.names without 'universe'), N of them, one DOF each
#   gravity gx gy gz      m/s^2 in the world (base) frame: MuJoCo m.opt.gravity,
#                         Pinocchio model.gravity.linear
# then {STATES} states of 8 lines each, SI units (rad, m, N, N m):
#   q qd qdd              the state and the accelerations asked for (N each); q uniform in
#                         [-1, 1] (slide/prismatic joints [-0.3, 0.3]), qd and qdd in [-1, 1]
#   M                     joint-space mass matrix, row-major N*N. MuJoCo: mj_fullM (with
#                         dof_armature on the diagonal). Pinocchio: crba, upper triangle
#                         copied to the lower.
#   bias                  M qdd + bias = rigid-body generalized force: Coriolis + centrifugal
#                         + gravity, no damping. MuJoCo qfrc_bias, Pinocchio nonLinearEffects
#   gravity_torque        bias at qd = 0. MuJoCo qfrc_bias with qvel = 0, Pinocchio
#                         computeGeneralizedGravity
#   damping               per-joint viscous damping coefficients (MuJoCo dof_damping,
#                         Pinocchio model.damping), repeated in every state
#   tau                   inverse dynamics with damping: M qdd + bias + damping * qd.
#                         MuJoCo: qfrc_inverse of mj_inverse; Pinocchio: rnea + damping * qd
# MuJoCo arms (acrobot cartpole pendulum reacher hopper swimmer6, dm_control 1.0.52 MJCF):
# constraints and contacts disabled, opt.density = opt.viscosity = 0 (no fluid forces); the
# arm is the joints from the world to the tip body, other joints (none in these files) at 0.
# A body's joints act in their order in the file (hopper torso: rootx, rootz, rooty;
# swimmer6 head: rootx, rooty, rootz), each about its own anchor (jnt_pos: swimmer6 hinges at
# (0, -0.05, 0) in their body). Pinocchio arms: ur5 (6 joints) and panda (7 joints, with
# {' and '.join(PANDA_LOCKED)} locked at 0 by buildReducedModel), example-robot-data 6.0.0 URDFs.
# Joints with nonzero stiffness / armature / frictionloss (Pinocchio: armature / friction):
"""
    head += "".join(f"#   {n}\n" for n in notes) if notes else "#   none\n"
    head += "# Largest differences in the internal checks (all states, all arms):\n"
    head += "".join(f"#   {k}: {v:.3e}\n" for k, v in maxdiff.items())
    head += "# Smallest eigenvalue of M over the states: " + ", ".join(
        f"{k} {v:.3e}" for k, v in mineigs.items()) + "\n"
    sys.stdout.write(head + "\n".join(body) + "\n")


if __name__ == "__main__":
    main()
