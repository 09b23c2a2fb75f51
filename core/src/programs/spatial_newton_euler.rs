//! The recursive Newton-Euler algorithm unrolled for one spatial arm, each link's quantities in
//! its own frame, so that the constant parts of the joints' transformations (a Denavit-Hartenberg
//! twist of pi/2 is a permutation with a sign) fold into the program and only each joint's
//! motion costs arithmetic.
//!
//! Joint `i`'s transformation is `pre * motion(q_i) * post` (`frames::joint_parts`). The point
//! `A_i`, `pre`'s origin, is on the joint's axis; in link `i`'s frame it sits at
//! `-post_R^T post_p`, a constant, as is the axis `z_i = post_R^T u`. With `Q_i` the rotation
//! taking link `i - 1`'s coordinates to link `i`'s, `w`, `dw` the angular velocity and
//! acceleration and `a` the acceleration of the frame's origin:
//!
//! ```text
//! w_i  = Q_i w_{i-1} + z_i qd_i                                 (a slide: Q_i w_{i-1})
//! dw_i = Q_i dw_{i-1} + z_i qdd_i + (Q_i w_{i-1}) x z_i qd_i    (a slide: Q_i dw_{i-1})
//! a_A  = Q_i (a_{i-1} + dw_{i-1} x pre_p + w_{i-1} x (w_{i-1} x pre_p))
//! a_i  = a_A + dw_i x r_i + w_i x (w_i x r_i)                   (r_i = post_R^T post_p)
//!        (a slide: r_i + z_i q_i, and + 2 w_i x z_i qd_i + z_i qdd_i)
//! ```
//!
//! from `a_0 = -g`; inwards, each link's force `f` and moment `n` about its origin gather the
//! links beyond, the torque is `z_i . (n_i + r_i x f_i)` (the moment about `A_i`) or the force
//! `z_i . f_i`, and link `i - 1` receives `Q_i^T f_i` and `Q_i^T (n_i + r_i x f_i) + pre_p x
//! Q_i^T f_i`.

use crate::algebra::ring::int;
use crate::mechanics::planar::JointKind;
use crate::mechanics::spatial::frames::{joint_parts, link_bodies, motion};
use crate::mechanics::spatial::spec::SpatialArmSpec;
use crate::programs::method::Method;
use crate::programs::packed::Packed;
use crate::programs::spatial::{cross, dot, Nodes};
use crate::programs::unrolled::Terms;
use crate::slp::{Id, Input, Program};

pub(crate) type V3 = [Id; 3];

pub(crate) fn add(p: &mut Program, a: &V3, b: &V3) -> V3 {
    core::array::from_fn(|k| p.add(a[k], b[k]))
}

pub(crate) fn scale(p: &mut Program, a: &V3, s: Id) -> V3 {
    core::array::from_fn(|k| p.mul(a[k], s))
}

/// `w x (w x r) + dw x r`: the acceleration of a point `r` from the origin of a body turning at
/// `w` and accelerating at `dw`, less the origin's.
fn carried(p: &mut Program, w: &V3, dw: &V3, r: &V3) -> V3 {
    let wr = cross(p, w, r);
    let centripetal = cross(p, w, &wr);
    let tangential = cross(p, dw, r);
    add(p, &centripetal, &tangential)
}

/// A joint's constants as nodes, and its rotation `Q_i` in three factors applied one by one.
pub(crate) struct Joint {
    pub(crate) kind: JointKind,
    pub(crate) pre: Nodes,
    turn: Nodes,
    post: Nodes,
    /// The axis in the link's frame, and the vector from `A_i` to the link frame's origin.
    pub(crate) z: V3,
    pub(crate) r: V3,
}

impl Joint {
    pub(crate) fn new(p: &mut Program, arm: &SpatialArmSpec, j: usize) -> Self {
        let spec = &arm.joints[j];
        let (pre, u, post) = joint_parts(spec);
        let pre = Nodes::of(p, &pre);
        let post = Nodes::of(p, &post);
        let turn = match spec.kind {
            JointKind::Revolute => Nodes::of(p, &motion(spec.kind, &u, j)),
            // A slide does not turn: its rotation is the identity.
            JointKind::Prismatic => {
                Nodes::of(p, &crate::mechanics::spatial::frames::Frame::identity())
            }
        };
        let u: V3 = core::array::from_fn(|k| p.poly(&u[k]));
        let z = post.rotate_back(p, &u);
        let r = post.rotate_back(p, &post.p);
        Self {
            kind: spec.kind,
            pre,
            turn,
            post,
            z,
            r,
        }
    }

    /// `Q_i v`: from link `i - 1`'s axes to link `i`'s.
    pub(crate) fn inward(&self, p: &mut Program, v: &V3) -> V3 {
        let v = self.pre.rotate_back(p, v);
        let v = self.turn.rotate_back(p, &v);
        self.post.rotate_back(p, &v)
    }

    /// `Q_i^T v`: from link `i`'s axes to link `i - 1`'s.
    pub(crate) fn outward(&self, p: &mut Program, v: &V3) -> V3 {
        let v = self.post.rotate(p, v);
        let v = self.turn.rotate(p, &v);
        self.pre.rotate(p, &v)
    }
}

/// The joint forces of [`Terms`] by the unrolled recursion; `with_joint_terms` adds armature
/// times acceleration and friction (`damping qd + frictionloss sign(qd)`) where the terms have
/// accelerations and rates respectively.
pub(crate) fn inverse_dynamics(
    arm: &SpatialArmSpec,
    terms: Terms,
    with_joint_terms: bool,
) -> Method {
    let mut p = Program::new();
    let torques = newton_euler(&mut p, arm, terms, with_joint_terms);
    let outputs = torques
        .into_iter()
        .enumerate()
        .map(|(j, t)| (format!("t{}", j + 1), t))
        .collect();
    Method::new(p, outputs).described(DESCRIPTION)
}

/// How the recursion's methods are evaluated, for their docs.
pub(crate) const DESCRIPTION: &str = "the recursive Newton-Euler algorithm unrolled, each link in its own frame, the joints' constant transformations folded in";

/// Joint `j`'s friction `damping qd + frictionloss sign(qd)`.
pub(crate) fn friction(p: &mut Program, arm: &SpatialArmSpec, j: usize) -> Id {
    let spec = &arm.joints[j];
    let qd = p.input(Input::Qd(j));
    let damping = p.poly(&spec.damping);
    let viscous = p.mul(damping, qd);
    let loss = p.poly(&spec.frictionloss);
    let sign = p.sign(qd);
    let coulomb = p.mul(loss, sign);
    p.add(viscous, coulomb)
}

/// Joint `j`'s spring torque `stiffness (q - springref)`, if it has a spring: part of the
/// static torques g(q), as its energy is part of the potential.
pub(crate) fn spring(p: &mut Program, arm: &SpatialArmSpec, j: usize) -> Option<Id> {
    let spec = &arm.joints[j];
    if !spec.sprung() {
        return None;
    }
    let q = p.input(Input::Q(j));
    let rest = p.poly(&spec.springref);
    let stretch = p.sub(q, rest);
    let k = p.poly(&spec.stiffness);
    Some(p.mul(k, stretch))
}

/// The joints' springs' energy `sum stiffness (q - springref)^2 / 2`, if any joint has one.
pub(crate) fn spring_energy(p: &mut Program, arm: &SpatialArmSpec) -> Option<Id> {
    let mut total: Option<Id> = None;
    for (j, spec) in arm.joints.iter().enumerate() {
        let Some(torque) = spring(p, arm, j) else {
            continue;
        };
        let q = p.input(Input::Q(j));
        let rest = p.poly(&spec.springref);
        let stretch = p.sub(q, rest);
        let twice = p.mul(torque, stretch);
        let half = p.constant(crate::algebra::ring::ratio(1, 2));
        let e = p.mul(half, twice);
        total = Some(match total {
            Some(t) => p.add(t, e),
            None => e,
        });
    }
    total
}

/// The joints' friction `damping qd + frictionloss sign(qd)` alone.
pub(crate) fn friction_method(arm: &SpatialArmSpec) -> Method {
    let mut p = Program::new();
    let outputs = (0..arm.joints.len())
        .map(|j| (format!("f{}", j + 1), friction(&mut p, arm, j)))
        .collect();
    Method::new(p, outputs)
}

/// A link's inertial force and its moment about the link frame's origin, from the link's
/// angular velocity `w` and acceleration `dw` and its origin's acceleration `a` (gravity
/// included), all in the link's axes: `m a_c` and `I dw + w x I w + c x m a_c`.
fn inertial_load(
    p: &mut Program,
    spec: &crate::mechanics::spatial::spec::SpatialBody,
    w: &V3,
    dw: &V3,
    a: &V3,
) -> (V3, V3) {
    let mass = p.poly(&spec.mass);
    let com: V3 = core::array::from_fn(|k| p.poly(&spec.com[k]));
    let carried_c = carried(p, w, dw, &com);
    let a_com = add(p, a, &carried_c);
    let force = scale(p, &a_com, mass);
    let [xx, yy, zz, xy, xz, yz] = core::array::from_fn(|k| p.poly(&spec.inertia[k]));
    let tensor = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]];
    let times = |p: &mut Program, v: &V3| -> V3 {
        core::array::from_fn(|i| {
            let terms: Vec<Id> = (0..3).map(|k| p.mul(tensor[i][k], v[k])).collect();
            crate::programs::spatial::sum(p, &terms)
        })
    };
    let i_dw = times(p, dw);
    let i_w = times(p, w);
    let gyro = cross(p, w, &i_w);
    let about_com = add(p, &i_dw, &gyro);
    let lever = cross(p, &com, &force);
    (force, add(p, &about_com, &lever))
}

/// A link's motion in its own axes: angular velocity `w` and acceleration `dw`, the
/// acceleration `a` of its frame's origin (less gravity's), and `r`, from the point `A_i` on
/// its joint's axis to that origin.
pub(crate) struct Motion {
    pub(crate) w: V3,
    pub(crate) dw: V3,
    pub(crate) a: V3,
    pub(crate) r: V3,
}

/// The outward pass: every link's [`Motion`] with the rates, accelerations and gravity that
/// `terms` keeps.
pub(crate) fn motions(
    p: &mut Program,
    arm: &SpatialArmSpec,
    joints: &[Joint],
    terms: Terms,
) -> Vec<Motion> {
    let zero = p.constant(int(0));
    let rate = |p: &mut Program, on: bool, input: Input| if on { p.input(input) } else { zero };
    let (mut w, mut dw) = ([zero; 3], [zero; 3]);
    let mut a: V3 = if terms.gravity {
        core::array::from_fn(|k| {
            let g = p.poly(&arm.gravity[k]);
            p.neg(g)
        })
    } else {
        [zero; 3]
    };
    let mut out = Vec::with_capacity(joints.len());
    for (j, joint) in joints.iter().enumerate() {
        let qd = rate(p, terms.rates, Input::Qd(j));
        let qdd = rate(p, terms.accelerations, Input::Qdd(j));
        let carried_a = carried(p, &w, &dw, &joint.pre.p);
        let at_axis = add(p, &a, &carried_a);
        let a_axis = joint.inward(p, &at_axis);
        let w_in = joint.inward(p, &w);
        let dw_in = joint.inward(p, &dw);
        let (r, slide_terms) = match joint.kind {
            JointKind::Revolute => {
                let spin = scale(p, &joint.z, qd);
                w = add(p, &w_in, &spin);
                let push = scale(p, &joint.z, qdd);
                let gyro = cross(p, &w_in, &spin);
                let sum = add(p, &dw_in, &push);
                dw = add(p, &sum, &gyro);
                (joint.r, [zero; 3])
            }
            JointKind::Prismatic => {
                w = w_in;
                dw = dw_in;
                let q = p.input(Input::Q(j));
                let along = scale(p, &joint.z, q);
                let r = add(p, &joint.r, &along);
                let v_rel = scale(p, &joint.z, qd);
                let coriolis = cross(p, &w, &v_rel);
                let two = p.constant(int(2));
                let coriolis = scale(p, &coriolis, two);
                let a_rel = scale(p, &joint.z, qdd);
                (r, add(p, &coriolis, &a_rel))
            }
        };
        let carried_o = carried(p, &w, &dw, &r);
        let sum = add(p, &a_axis, &carried_o);
        a = add(p, &sum, &slide_terms);
        out.push(Motion { w, dw, a, r });
    }
    out
}

/// The inward pass: the joint forces that carry each link's `loads` (force, and moment about
/// its frame's origin, in its axes) and everything beyond it, read on each joint's axis.
/// Links `last + 1..` carry nothing: the pass starts at `last`.
pub(crate) fn transmitted(
    p: &mut Program,
    joints: &[Joint],
    motions: &[Motion],
    loads: &[(V3, V3)],
    last: usize,
) -> Vec<Id> {
    let zero = p.constant(int(0));
    let (mut f_out, mut n_out) = ([zero; 3], [zero; 3]);
    let mut torques = vec![zero; joints.len()];
    for j in (0..=last).rev() {
        let (force, moment) = &loads[j];
        let f = add(p, force, &f_out);
        let n_origin = add(p, moment, &n_out);
        let shift = cross(p, &motions[j].r, &f);
        let n_axis = add(p, &n_origin, &shift);
        let joint = &joints[j];
        torques[j] = match joint.kind {
            JointKind::Revolute => dot(p, &joint.z, &n_axis),
            JointKind::Prismatic => dot(p, &joint.z, &f),
        };
        if j > 0 {
            f_out = joint.outward(p, &f);
            let back = joint.outward(p, &n_axis);
            let lever = cross(p, &joint.pre.p, &f_out);
            n_out = add(p, &back, &lever);
        }
    }
    torques
}

/// [`inverse_dynamics`]'s torques as nodes of `p`.
pub(crate) fn newton_euler(
    p: &mut Program,
    arm: &SpatialArmSpec,
    terms: Terms,
    with_joint_terms: bool,
) -> Vec<Id> {
    let n = arm.joints.len();
    let joints: Vec<Joint> = (0..n).map(|j| Joint::new(p, arm, j)).collect();
    let motions = motions(p, arm, &joints, terms);
    // Each link's inertial force and moment about its origin, its payload's added.
    let loads: Vec<(V3, V3)> = motions
        .iter()
        .enumerate()
        .map(|(j, m)| {
            let mut load: Option<(V3, V3)> = None;
            for body in link_bodies(arm, j) {
                let (f, t) = inertial_load(p, &body, &m.w, &m.dw, &m.a);
                load = Some(match load {
                    None => (f, t),
                    Some((f0, t0)) => (add(p, &f0, &f), add(p, &t0, &t)),
                });
            }
            load.unwrap_or_else(|| unreachable!("a link carries its own body"))
        })
        .collect();
    let mut torques = transmitted(p, &joints, &motions, &loads, n - 1);
    for (j, spec) in arm.joints.iter().enumerate() {
        if with_joint_terms && terms.accelerations {
            let armature = p.poly(&spec.armature);
            let qdd = p.input(Input::Qdd(j));
            let reflected = p.mul(armature, qdd);
            torques[j] = p.add(torques[j], reflected);
        }
        if with_joint_terms && terms.rates {
            let f = friction(p, arm, j);
            torques[j] = p.add(torques[j], f);
        }
        if terms.gravity {
            if let Some(s) = spring(p, arm, j) {
                torques[j] = p.add(torques[j], s);
            }
        }
    }
    torques
}

/// The largest spatial derivative program emitted as code. Above planar arms' limit
/// (`derivative::MAX_OPS`, 4000) because the alternative costs more here: a seven-joint arm's
/// inverse dynamics in run-time jets took 5.4 us (45 times the inverse dynamics, slower than
/// Pinocchio's `computeRNEADerivatives`), and the Panda's program with full inertia tensors
/// is 8,303 operations, which a user crate calling it compiles in about 0.3 s more
/// (docs/performance.md).
const MAX_DERIVATIVE_OPS: usize = 10_000;

/// `(dtau/dq, dtau/dqd)` of [`inverse_dynamics`], row-major each: the unrolled recursion
/// differentiated at compile time along every angle and rate (`derivative`); `None` past
/// [`MAX_DERIVATIVE_OPS`] operations, where the trait's default (the generated inverse
/// dynamics in run-time jets) costs a user's build less. With it, where it is emitted,
/// `(-W dtau/dq, -W dtau/dqd)` for the run-time `W = M^-1`, row-major each: the same recursion
/// run backward from the torques weighted by the rows of `-W`, eight rows at a time
/// ([`adjoint`](crate::adjoint::adjoint)), the forward dynamics' derivatives at the
/// accelerations (`None` where the program has what that does not differentiate).
pub(crate) fn inverse_dynamics_derivatives(
    arm: &SpatialArmSpec,
) -> (Option<Method>, Option<Packed>) {
    let n = arm.joints.len();
    if n > crate::programs::derivative::MAX_LINKS {
        return (None, None);
    }
    let mut p = Program::new();
    let torques = newton_euler(&mut p, arm, Terms::ALL, true);
    let directions: Vec<Input> = (0..n).map(Input::Q).chain((0..n).map(Input::Qd)).collect();
    let packed = crate::programs::packed::pack(&p, &torques, &directions);
    let adjoint = crate::programs::adjoint::adjoint(&p, &torques, n, &directions, 8);
    let Ok(jacobian) = crate::programs::derivative::differentiate(&mut p, &torques, &directions)
    else {
        return (None, None);
    };
    let mut outputs = Vec::with_capacity(2 * n * n);
    for (wrt, offset) in [("q", 0), ("qd", n)] {
        for (i, row) in jacobian.iter().enumerate() {
            for j in 0..n {
                outputs.push((format!("dtau{}_d{wrt}{}", i + 1, j + 1), row[offset + j]));
            }
        }
    }
    let mut method = Method::new(p, outputs).described(
        "the unrolled recursive Newton-Euler algorithm differentiated at compile time, operation by operation, four directions at a time",
    );
    method.packed = packed.map(|pk| Box::new(by_matrix(pk, n)));
    let ops = method.op_count();
    if ops.mul + ops.add > MAX_DERIVATIVE_OPS {
        return (None, None);
    }
    (Some(method), adjoint.map(|pk| by_matrix(pk, n)))
}

/// `pk`'s derivatives, row by row over `(q, qd)`, in the outputs' order: `d/dq` row by row,
/// then `d/dqd`.
fn by_matrix(mut pk: Packed, n: usize) -> Packed {
    let by_row = std::mem::take(&mut pk.derivatives);
    for offset in [0, n] {
        for i in 0..n {
            pk.derivatives
                .extend_from_slice(&by_row[i * 2 * n + offset..i * 2 * n + offset + n]);
        }
    }
    pk
}
