"""Load the model files written by our exporter (tests/data/export/) with MuJoCo and
Pinocchio, and write their joint-space dynamics as the fixture tests/data/export_peers.txt,
in the same format as tests/data/models_peers.txt (see bench/models/fixtures.py).

Run by hand (CI installs neither MuJoCo nor Pinocchio), from the repository root:

    python3 bench/models/load_exports.py > tests/data/export_peers.txt

It needs numpy, `mujoco` and `pin` (Pinocchio) from PyPI. The checked-in file was produced
with Python 3.11.7, mujoco 4.0.1, pin (Pinocchio) 4.1.0 and numpy 2.4.6; the versions are
also written into the file's first comment lines. Diagnostics go to stderr.

Files, in sorted order of their names, one arm each (`arm NAME` is the file name):

- *.xml (MJCF): mujoco.MjModel.from_xml_path, then constraints and contacts are disabled and
  fluid forces are switched off (opt.density = opt.viscosity = 0). The arm is the chain of
  joints from the world to the body `tool` (every export is one chain of 1-DoF joints; the
  script stops if there are other joints). gravity is m.opt.gravity. M is mj_fullM (with
  dof_armature on its diagonal), bias is qfrc_bias, gravity_torque is qfrc_bias at qvel = 0,
  both plus the joint springs' stiffness (q - springref) (MuJoCo's qfrc_passive; the crate
  counts springs in its static torques g = dV/dq), damping is dof_damping, tau is qfrc_inverse of mj_inverse. MuJoCo's frictionloss is a
  constraint, disabled here, so it is in none of the numbers.
- *.urdf: pinocchio.buildModelFromUrdf. gravity is Pinocchio's default model.gravity
  (0 0 -9.81). M is crba (upper triangle copied to the lower), bias nonLinearEffects,
  gravity_torque computeGeneralizedGravity, damping model.damping, tau = rnea + damping * qd.
  Pinocchio's friction (URDF <dynamics friction>) is in none of the numbers. URDF
  `continuous` joints are Pinocchio JointModelRUB* joints with nq = 2 (cos, sin): the
  fixture's q is the angle, and Pinocchio is given (cos q, sin q).

Each .xml is also loaded with pinocchio.buildModelFromMJCF and its M and nonLinearEffects
(with Pinocchio's gravity set to MuJoCo's opt.gravity) are compared with MuJoCo's at the same
states; and each .urdf arm is compared with the .xml export of the same arm. Those numbers
are only reported on stderr, not written to the fixture.

Three random states per arm come from numpy.random.default_rng(SEED), one generator used
by all arms in the order written. q is uniform in [-1, 1]; slide/prismatic joints: [0, 0.3]
when the joint's range is [0, 0.5], otherwise [-0.3, 0.3]. qd and qdd are uniform in [-1, 1].

Checks made before anything is written, stopping on failure: M is symmetric and positive
definite; MuJoCo's qfrc_inverse = M qdd + qfrc_bias + damping qd + springs and
qfrc_passive = -damping qd - springs (to 1e-10); Pinocchio's rnea = M qdd + nle (to 1e-10) and crba's M equals the
columns rnea(q, 0, e_i) without gravity; bias at qd = 0 equals gravity_torque. Anything the
loaders print (on stdout or stderr, at the file-descriptor level), Python warnings and
MuJoCo's data.warning counters are reported on stderr and in the file's comments.
"""

import os
import platform
import sys
import tempfile
import warnings
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fixtures import (  # noqa: E402  (shared with the models' fixture)
    body_path,
    chain_joints,
    check_spd,
    evaluate,
    fmt,
    line,
    log,
    rigid_bodies_only,
)

ROOT = Path(__file__).resolve().parents[2]
EXPORT = ROOT / "tests" / "data" / "export"
SEED = 20240612
STATES = 3
TOL = 1e-10
TIP = "tool"


def mx(a):
    a = np.asarray(a, dtype=float)
    return float(np.max(np.abs(a))) if a.size else 0.0


def captured(fn, *args):
    """Call fn(*args), returning (result, exception, text printed on fd 1/2, Python warnings)."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    result, exc = None, None
    with tempfile.TemporaryFile(mode="w+b") as tmp, warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        os.dup2(tmp.fileno(), 1)
        os.dup2(tmp.fileno(), 2)
        try:
            result = fn(*args)
        except Exception as e:  # noqa: BLE001 - reported, not swallowed
            exc = e
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for fd in saved:
                os.close(fd)
        tmp.seek(0)
        text = tmp.read().decode(errors="replace").strip()
        pywarn = [f"{x.category.__name__}: {x.message}" for x in w]
    return result, exc, text, pywarn


def load(what, name, fn, path, loadlog):
    res, exc, text, pywarn = captured(fn, str(path))
    msgs = ([f"printed: {text!r}"] if text else []) + [f"warning: {x}" for x in pywarn]
    if exc is not None:
        msgs.append(f"FAILED: {type(exc).__name__}: {exc}")
    loadlog.append(f"{name} ({what}): " + ("; ".join(msgs) if msgs else "loaded, nothing printed"))
    log(loadlog[-1])
    return res, exc


def random_state(rng, slide_ranges):
    """slide_ranges: per joint None (rotary) or (lo, hi) of the slide's draw."""
    n = len(slide_ranges)
    q = rng.uniform(-1.0, 1.0, n)
    for i, r in enumerate(slide_ranges):
        if r is not None:
            q[i] = rng.uniform(r[0], r[1])
    qd = rng.uniform(-1.0, 1.0, n)
    qdd = rng.uniform(-1.0, 1.0, n)
    return q, qd, qdd


def slide_draw(lo, hi):
    return (0.0, 0.3) if (lo, hi) == (0.0, 0.5) else (-0.3, 0.3)


def record(maxdiff, key, v, limit=TOL, name=""):
    if limit is not None and v > limit:
        raise SystemExit(f"{name}: {key} = {v}")
    maxdiff[key] = max(maxdiff.get(key, 0.0), v)


def inertia_margin(m, bodies):
    """Smallest (I1 + I2 - I3) / max(I) over the bodies' principal inertias (triangle inequality)."""
    out = []
    for b in bodies:
        i = np.sort(np.asarray(m.body_inertia[b], dtype=float))
        if m.body_mass[b] > 0:
            out.append((mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b), float((i[0] + i[1] - i[2]) / i[2])))
    return out


def pin_q(model, q):
    """The fixture's q (one angle or position per joint) as Pinocchio's configuration."""
    qp = np.zeros(model.nq)
    for i, j in enumerate(list(model.joints)[1:]):
        if j.nq == 1:
            qp[j.idx_q] = q[j.idx_v]
        elif j.nq == 2 and j.shortname().startswith("JointModelRUB"):
            qp[j.idx_q] = np.cos(q[j.idx_v])
            qp[j.idx_q + 1] = np.sin(q[j.idx_v])
        else:
            raise SystemExit(f"joint {model.names[i + 1]} ({j.shortname()}) has nq {j.nq}")
    return qp


def pin_dyn(model, data, q, qd, qdd=None):
    qp = pin_q(model, q)
    M = np.array(pin.crba(model, data, qp))
    M = np.triu(M) + np.triu(M, 1).T
    nle = np.array(pin.nonLinearEffects(model, data, qp, qd))
    rnea = None if qdd is None else np.array(pin.rnea(model, data, qp, qd, qdd))
    return qp, M, nle, rnea


def mujoco_arm(name, path, rng, notes, maxdiff, mineigs, loadlog, states_out):
    m, exc = load("mujoco.MjModel.from_xml_path", name, mujoco.MjModel.from_xml_path, path, loadlog)
    if exc is not None:
        notes.append(f"{name}: MuJoCo load failed: {exc}")
        return []
    rigid_bodies_only(m)

    chain = body_path(m, TIP)
    joints = chain_joints(m, chain)
    if len(joints) != m.njnt or m.nv != m.njnt or m.nq != m.njnt:
        raise SystemExit(f"{name}: not a single chain of 1-DoF joints (njnt {m.njnt}, nq {m.nq}, nv {m.nv})")
    jnames = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, j) for j in joints]
    slide_ranges = []
    for j in joints:
        t = int(m.jnt_type[j])
        if t == int(mujoco.mjtJoint.mjJNT_SLIDE):
            lo, hi = (float(x) for x in m.jnt_range[j]) if m.jnt_limited[j] else (None, None)
            slide_ranges.append(slide_draw(lo, hi))
        elif t == int(mujoco.mjtJoint.mjJNT_HINGE):
            slide_ranges.append(None)
        else:
            raise SystemExit(f"{name}: joint {j} is neither hinge nor slide")
    log(f"{name}: n {len(joints)} joints {jnames}; bodies "
        f"{[mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b) for b in chain]}; body_mass "
        f"{[float(m.body_mass[b]) for b in chain]}; slide draws {slide_ranges}; "
        f"inertia triangle margin (I1+I2-I3)/I3 {inertia_margin(m, chain)}")

    dofs = np.array([m.jnt_dofadr[j] for j in joints])
    qadr = np.array([m.jnt_qposadr[j] for j in joints])
    for j, jn in zip(joints, jnames):
        d = m.jnt_dofadr[j]
        k, a, f = float(m.jnt_stiffness[j]), float(m.dof_armature[d]), float(m.dof_frictionloss[d])
        if k != 0 or a != 0 or f != 0:
            notes.append(f"{name} {jn}: stiffness {fmt(k)} armature {fmt(a)} frictionloss {fmt(f)}")
    damping = m.dof_damping[dofs].copy()
    # Joint springs, stiffness (q - springref): MuJoCo's qfrc_passive; the crate counts them in
    # its static torques g = dV/dq, so they are added to bias and gravity_torque here.
    stiffness = np.array([float(m.jnt_stiffness[j]) for j in joints])
    springref = np.array([float(m.qpos_spring[m.jnt_qposadr[j]]) for j in joints])

    out = [f"arm {name}", "joints " + " ".join(jnames), line("gravity", m.opt.gravity)]
    d, dg, di = mujoco.MjData(m), mujoco.MjData(m), mujoco.MjData(m)
    Mfull = np.zeros((m.nv, m.nv))
    states = []
    for _ in range(STATES):
        q, qd, qdd = random_state(rng, slide_ranges)
        evaluate(m, (d, dg, di), dofs, qadr, q, qd, qdd)
        for dd in (d, dg, di):
            for w in range(len(dd.warning)):
                if dd.warning[w].number:
                    msg = f"{name}: MuJoCo data warning {mujoco.mjtWarning(w).name} x{dd.warning[w].number}"
                    log(msg)
                    loadlog.append(msg)

        mujoco.mj_fullM(m, d, Mfull)
        M = Mfull[np.ix_(dofs, dofs)].copy()
        springs = stiffness * (q - springref)
        bias = d.qfrc_bias[dofs].copy() + springs
        grav = dg.qfrc_bias[dofs].copy() + springs
        tau = di.qfrc_inverse[dofs].copy()
        passive = d.qfrc_passive[dofs].copy()

        asym, mineig = check_spd(name, M)
        record(maxdiff, "M asymmetry", asym, None)
        record(maxdiff, "mj_inverse - (M qdd + bias + damping qd)", mx(tau - (M @ qdd + bias + damping * qd)), name=name)
        record(maxdiff, "qfrc_passive + damping qd + springs", mx(passive + damping * qd + springs), name=name)
        record(maxdiff, "mj_inverse bias - mj_forward bias", mx(di.qfrc_bias[dofs] + springs - bias), name=name)
        rne = np.zeros(m.nv)
        mujoco.mj_rne(m, dg, 0, rne)
        record(maxdiff, "gravity_torque - mj_rne(qd=0) - springs", mx(rne[dofs] + springs - grav), name=name)
        mineigs[name] = min(mineigs.get(name, np.inf), mineig)
        states.append((q, qd, qdd, M, bias, grav, damping, tau))

        out += [line("q", q), line("qd", qd), line("qdd", qdd), line("M", M), line("bias", bias),
                line("gravity_torque", grav), line("damping", damping), line("tau", tau)]
    states_out[name] = (jnames, np.array(m.opt.gravity), states)
    return out


class Diffs:
    """Largest absolute difference per quantity, and the largest |reference| it is relative to."""

    def __init__(self):
        self.abs, self.ref = {}, {}

    def add(self, key, value, ref):
        self.abs[key] = max(self.abs.get(key, 0.0), mx(np.asarray(value) - np.asarray(ref)))
        self.ref[key] = max(self.ref.get(key, 0.0), mx(ref))

    def __str__(self):
        def rel(k, a):
            return a / self.ref[k] if self.ref[k] else (0.0 if a == 0 else float("inf"))

        return ", ".join(f"{k} {a:.3e} (relative {rel(k, a):.3e})" for k, a in self.abs.items())


def pinocchio_mjcf_compare(name, path, mj, loadlog, pin_mjcf):
    """Load the .xml with pinocchio.buildModelFromMJCF and compare with MuJoCo's numbers."""
    model, exc = load("pinocchio.buildModelFromMJCF", name, pin.buildModelFromMJCF, path, loadlog)
    if exc is not None:
        pin_mjcf[name] = f"load FAILED: {type(exc).__name__}: {exc}"
        return
    jnames, grav_mj, states = mj
    names = list(model.names)[1:]
    info = (f"nq {model.nq} nv {model.nv} joints {names} types {[j.shortname() for j in list(model.joints)[1:]]} "
            f"gravity {model.gravity.linear.tolist()} (MuJoCo {grav_mj.tolist()}) "
            f"damping {np.asarray(model.damping).tolist()} armature {np.asarray(model.armature).tolist()} "
            f"friction {np.asarray(model.friction).tolist()} limits "
            f"{list(zip(np.asarray(model.lowerPositionLimit).tolist(), np.asarray(model.upperPositionLimit).tolist()))}")
    if names != jnames or model.nv != len(jnames) or model.nq != len(jnames):
        pin_mjcf[name] = f"joints differ from MuJoCo's: {info}"
        return
    default_g = model.gravity.linear.copy()
    data = model.createData()
    r = Diffs()
    for q, qd, qdd, M, bias, grav, damping, tau in states:
        model.gravity.linear[:] = default_g
        _, _, nle_default, _ = pin_dyn(model, data, q, qd)
        model.gravity.linear[:] = grav_mj
        qp, Mp, nle, rnea = pin_dyn(model, data, q, qd, qdd)
        gp = np.array(pin.computeGeneralizedGravity(model, data, qp))
        r.add("M", Mp, M)
        r.add("nle", nle, bias)
        r.add("gravity", gp, grav)
        r.add("damping", np.asarray(model.damping), damping)
        r.add("rnea + damping qd vs mj_inverse", rnea + np.asarray(model.damping) * qd, tau)
        r.add("nle with Pinocchio's own gravity", nle_default, bias)
    model.gravity.linear[:] = default_g
    pin_mjcf[name] = f"loads; max difference (gravity set to MuJoCo's) {r}; {info}"


def pinocchio_arm(name, path, rng, notes, maxdiff, mineigs, loadlog, states_out):
    model, exc = load("pinocchio.buildModelFromUrdf", name, pin.buildModelFromUrdf, path, loadlog)
    if exc is not None:
        notes.append(f"{name}: Pinocchio load failed: {exc}")
        return []
    data = model.createData()
    jnames = list(model.names)[1:]
    slide_ranges = []
    for i, j in enumerate(list(model.joints)[1:]):
        if j.nv != 1 or j.idx_v != i:
            raise SystemExit(f"{name}: joint {jnames[i]} has nv {j.nv}, idx_v {j.idx_v}")
        s = j.shortname()
        if "Prismatic" in s or s.startswith("JointModelP"):
            slide_ranges.append(slide_draw(float(model.lowerPositionLimit[j.idx_q]),
                                           float(model.upperPositionLimit[j.idx_q])))
        else:
            slide_ranges.append(None)
    damping = np.array(model.damping, dtype=float)
    for i, jn in enumerate(jnames):
        a, f = float(model.armature[i]), float(model.friction[i])
        if a != 0 or f != 0:
            notes.append(f"{name} {jn}: armature {fmt(a)} friction {fmt(f)}")
    log(f"{name}: n {model.nv} (nq {model.nq}) joints {jnames}; types "
        f"{[j.shortname() for j in list(model.joints)[1:]]}; damping {damping.tolist()}; armature "
        f"{[float(a) for a in model.armature]}; friction {[float(f) for f in model.friction]}; link masses "
        f"{[float(i.mass) for i in list(model.inertias)[1:]]}; frames {[f.name for f in model.frames]}; "
        f"slide draws {slide_ranges}")
    out = [f"arm {name}", "joints " + " ".join(jnames), line("gravity", model.gravity.linear)]
    states = []
    for _ in range(STATES):
        q, qd, qdd = random_state(rng, slide_ranges)
        qp, M, bias, rnea = pin_dyn(model, data, q, qd, qdd)
        g0 = model.gravity.linear.copy()
        model.gravity.linear[:] = 0.0
        Mcols = np.column_stack([pin.rnea(model, data, qp, np.zeros(model.nv), e) for e in np.eye(model.nv)])
        model.gravity.linear[:] = g0
        grav = np.array(pin.computeGeneralizedGravity(model, data, qp))
        nle0 = np.array(pin.nonLinearEffects(model, data, qp, np.zeros(model.nv)))
        tau = rnea + damping * qd

        asym, mineig = check_spd(name, M)
        record(maxdiff, "M asymmetry", asym, None)
        record(maxdiff, "rnea - (M qdd + nle)", mx(rnea - (M @ qdd + bias)), name=name)
        record(maxdiff, "computeGeneralizedGravity - nle(qd=0)", mx(grav - nle0), name=name)
        record(maxdiff, "crba M - rnea(q, 0, e_i) columns without gravity", mx(Mcols - M), name=name)
        mineigs[name] = min(mineigs.get(name, np.inf), mineig)
        states.append((q, qd, qdd, M, bias, grav, damping, tau))

        out += [line("q", q), line("qd", qd), line("qdd", qdd), line("M", M), line("bias", bias),
                line("gravity_torque", grav), line("damping", damping), line("tau", tau)]
    states_out[name] = (jnames, np.array(model.gravity.linear), states, model)
    return out


def urdf_vs_xml(urdf, xml, states_out, cross):
    """The URDF export (Pinocchio) at the .xml export's states (MuJoCo), same gravity."""
    if urdf not in states_out or xml not in states_out:
        return
    jn_u, _, _, model = states_out[urdf]
    jn_x, grav_mj, states = states_out[xml]
    if jn_u != jn_x:
        cross[urdf] = f"joint names differ: {jn_u} vs {jn_x}"
        return
    data = model.createData()
    g0 = model.gravity.linear.copy()
    model.gravity.linear[:] = grav_mj
    r = Diffs()
    diag = np.zeros(len(jn_u))
    for q, qd, qdd, M, bias, grav, damping, tau in states:
        qp, Mp, nle, _ = pin_dyn(model, data, q, qd)
        gp = np.array(pin.computeGeneralizedGravity(model, data, qp))
        D = M - Mp
        r.add("M", Mp, M)
        r.add("M off the diagonal", Mp - np.diag(np.diag(Mp)), M - np.diag(np.diag(M)))
        r.add("nle", nle, bias)
        r.add("gravity", gp, grav)
        r.add("damping", np.asarray(model.damping), damping)
        diag = np.maximum(diag, np.abs(np.diag(D)))
    model.gravity.linear[:] = g0
    cross[urdf] = f"vs {xml}: max difference {r}; max |diag(M_MuJoCo - M_Pinocchio)| {diag.tolist()}"


def main():
    rng = np.random.default_rng(SEED)
    files = sorted(p for p in EXPORT.iterdir() if p.suffix in (".xml", ".urdf"))
    notes, maxdiff, mineigs, loadlog, body = [], {}, {}, [], []
    states_out, pin_mjcf, cross = {}, {}, {}
    for p in files:
        if p.suffix == ".xml":
            body += mujoco_arm(p.name, p, rng, notes, maxdiff, mineigs, loadlog, states_out)
        else:
            body += pinocchio_arm(p.name, p, rng, notes, maxdiff, mineigs, loadlog, states_out)
    for p in files:
        if p.suffix == ".xml" and p.name in states_out:
            pinocchio_mjcf_compare(p.name, p, states_out[p.name], loadlog, pin_mjcf)
        if p.suffix == ".urdf":
            urdf_vs_xml(p.name, p.with_suffix(".xml").name, states_out, cross)

    for k, v in maxdiff.items():
        log(f"max {k}: {v:.3e}")
    for k, v in mineigs.items():
        log(f"smallest eigenvalue of M, {k}: {v:.3e}")
    for n in notes:
        log("nonzero:", n)
    for k, v in pin_mjcf.items():
        log(f"pinocchio.buildModelFromMJCF {k}: {v}")
    for k, v in cross.items():
        log(f"Pinocchio {k} {v}")

    xmls = " ".join(p.name for p in files if p.suffix == ".xml")
    urdfs = " ".join(p.name for p in files if p.suffix == ".urdf")
    head = f"""\
# Written by bench/models/load_exports.py with Python {platform.python_version()}, mujoco {mujoco.__version__},
# pin (Pinocchio) {pin.__version__}, numpy {np.__version__}. numpy.random.default_rng({SEED}), {STATES} states per arm.
# The arms are the files in tests/data/export (written by our exporter), NAME = file name.
# Format: '#' lines are comments. Each arm starts with 'arm NAME', then
#   joints J1 J2 ...      the chain's joints (MuJoCo joint names in qpos order, or Pinocchio
#                         model.names without 'universe'), N of them, one DOF each
#   gravity gx gy gz      m/s^2 in the world (base) frame: MuJoCo m.opt.gravity,
#                         Pinocchio model.gravity.linear (its default; URDF has no gravity)
# then {STATES} states of 8 lines each, SI units (rad, m, N, N m):
#   q qd qdd              the state and the accelerations asked for (N each); q uniform in
#                         [-1, 1] (slide/prismatic joints: [0, 0.3] if their range is [0, 0.5],
#                         else [-0.3, 0.3]), qd and qdd in [-1, 1]. q is the joint angle also
#                         for URDF continuous joints (Pinocchio is given cos q, sin q).
#   M                     joint-space mass matrix, row-major N*N. MuJoCo: mj_fullM (with
#                         dof_armature on the diagonal). Pinocchio: crba, upper triangle
#                         copied to the lower.
#   bias                  M qdd + bias = rigid-body generalized force: Coriolis + centrifugal
#                         + gravity + joint springs stiffness (q - springref), no damping.
#                         MuJoCo qfrc_bias + springs, Pinocchio nonLinearEffects
#   gravity_torque        bias at qd = 0. MuJoCo qfrc_bias with qvel = 0 + springs, Pinocchio
#                         computeGeneralizedGravity
#   damping               per-joint viscous damping coefficients (MuJoCo dof_damping,
#                         Pinocchio model.damping), repeated in every state
#   tau                   inverse dynamics with damping: M qdd + bias + damping * qd.
#                         MuJoCo: qfrc_inverse of mj_inverse; Pinocchio: rnea + damping * qd
# MuJoCo arms ({xmls}): mujoco.MjModel.from_xml_path; constraints and contacts disabled,
# opt.density = opt.viscosity = 0. MuJoCo's frictionloss is a constraint, so it is disabled and
# in no number here (tau excludes it). Pinocchio arms ({urdfs}):
# pinocchio.buildModelFromUrdf; Pinocchio's friction is in no number either. Each arm is the
# chain of joints from the world to the body/link 'tool'; every file is one chain of 1-DoF joints.
# Joints with nonzero stiffness / armature / frictionloss (Pinocchio: armature / friction):
"""
    head += "".join(f"#   {n}\n" for n in notes) if notes else "#   none\n"
    head += "# Loading (text printed by the loaders, warnings, failures):\n"
    head += "".join(f"#   {x}\n" for x in loadlog if "buildModelFromMJCF" not in x)
    head += "# Largest differences in the internal checks (all states, all arms):\n"
    head += "".join(f"#   {k}: {v:.3e}\n" for k, v in maxdiff.items())
    head += "# Smallest eigenvalue of M over the states: " + ", ".join(
        f"{k} {v:.3e}" for k, v in mineigs.items()) + "\n"
    flat = [k for k, v in states_out.items() if max(mx(st[5]) for st in v[2]) < 1e-12]
    head += ("# gravity_torque is zero up to rounding (max |.| < 1e-12, compare with an absolute tolerance): "
             + (" ".join(flat) if flat else "none") + "\n")
    sys.stdout.write(head + "\n".join(body) + "\n")


if __name__ == "__main__":
    main()
