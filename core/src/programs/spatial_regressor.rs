//! The joint-force regressor of a spatial arm, unrolled: `tau = Y(q, qd, qdd) theta`, with
//! `theta` the standard parameters ([`SpatialParameter`]).
//!
//! A body held about a frame's origin by its mass `m`, first moment `h = m c` and inertia `J`
//! about the origin (all in the frame's axes) needs the force `m a + dw x h + w x (w x h)` and
//! the moment about the origin `J dw + w x J w + h x a`, both linear in `(m, h, J)`. Column `k`
//! of link `i` is therefore the joint forces that carry the body whose parameters are all zero
//! but parameter `k`, one. Joint `j` carries a wrench `(f, n)` on link `i` (moment about its
//! origin) with the torque `v . f + w . n`, `(w, v)` the twist link `i` has (angular velocity,
//! velocity of its origin) when joint `j` alone turns at unit rate: the outward pass of the
//! motion and of these twists is shared by every column, and each entry is one such product,
//! whose zeros fold away. The payload's ten parameters, in the tool frame, are a
//! constant linear map of the last link's: `h = m p + R h_t`, `J = R J_t R^T + m (|p|^2 E -
//! p p^T) + 2 (p . R h_t) E - p (R h_t)^T - (R h_t) p^T`.
//!
//! [`packed_regressor`] computes the same entries four joints per lane, as the derivatives of
//! the virtual power along the joints' virtual rates; the derive emits it for the base
//! regressor's AVX2 copy.

use crate::algebra::poly::Poly;
use crate::algebra::ring::int;
use crate::mechanics::planar::JointKind;
use crate::mechanics::spatial::frames::tool_frame;
use crate::mechanics::spatial::spec::{SpatialArmSpec, SpatialBody};
use crate::programs::method::Method;
use crate::programs::spatial::{cross, dot};
use crate::programs::spatial_newton_euler::{add, motions, scale, Joint, Motion, DESCRIPTION, V3};
use crate::programs::unrolled::Terms;
use crate::slp::{Id, Input, Program};

/// A body's ten standard parameters in Pinocchio's order: mass, first moment, then the inertia
/// about the frame's origin `xx, xy, yy, xz, yz, zz`.
pub const BODY_ENTRIES: [&str; 10] = ["m", "mx", "my", "mz", "xx", "xy", "yy", "xz", "yz", "zz"];

/// Whose a standard parameter is and which one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Entry {
    /// Entry `k` of [`BODY_ENTRIES`] of link `i`'s body (0-based).
    Link(usize, usize),
    /// Entry `k` of the payload's, in the tool frame.
    Payload(usize),
    /// Joint `j`'s armature.
    Armature(usize),
    /// Joint `j`'s viscous friction (`damping`).
    Damping(usize),
    /// Joint `j`'s Coulomb friction (`frictionloss`).
    Frictionloss(usize),
}

/// A standard parameter of a spatial arm.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpatialParameter {
    /// `m1`, `mx1`, .., `zz1`, `ia1`, `fv1`, `fc1`, `mp`, .., `zzp`.
    pub name: String,
    /// Which it is.
    pub entry: Entry,
}

/// The arm's standard parameters in the regressor's column order: each link's ten, then per
/// joint its armature, damping and frictionloss where it has them, then the payload's ten.
#[must_use]
pub fn standard_parameters(arm: &SpatialArmSpec) -> Vec<SpatialParameter> {
    let mut out = Vec::new();
    let n = arm.joints.len();
    for i in 0..n {
        for (k, e) in BODY_ENTRIES.iter().enumerate() {
            out.push(SpatialParameter {
                name: format!("{e}{}", i + 1),
                entry: Entry::Link(i, k),
            });
        }
    }
    for (j, spec) in arm.joints.iter().enumerate() {
        let terms = [
            (&spec.armature, "ia", Entry::Armature(j)),
            (&spec.damping, "fv", Entry::Damping(j)),
            (&spec.frictionloss, "fc", Entry::Frictionloss(j)),
        ];
        for (value, prefix, entry) in terms {
            if !crate::ring::Coefficient::is_zero(value) {
                out.push(SpatialParameter {
                    name: format!("{prefix}{}", j + 1),
                    entry,
                });
            }
        }
    }
    if arm.payload.is_some() {
        for (k, e) in BODY_ENTRIES.iter().enumerate() {
            out.push(SpatialParameter {
                name: format!("{e}p"),
                entry: Entry::Payload(k),
            });
        }
    }
    out
}

/// The standard parameters' values, exact (polynomials in run-time parameters).
#[must_use]
pub fn standard_values(arm: &SpatialArmSpec, parameters: &[SpatialParameter]) -> Vec<Poly> {
    let links: Vec<[Poly; 10]> = arm
        .joints
        .iter()
        .map(|j| SpatialBody::of_link(j).standard_parameters())
        .collect();
    let payload = arm.payload.as_ref().map(SpatialBody::standard_parameters);
    parameters
        .iter()
        .map(|s| match s.entry {
            Entry::Link(i, k) => links[i][k].clone(),
            Entry::Payload(k) => payload
                .as_ref()
                .map_or_else(Poly::default, |p| p[k].clone()),
            Entry::Armature(j) => arm.joints[j].armature.clone(),
            Entry::Damping(j) => arm.joints[j].damping.clone(),
            Entry::Frictionloss(j) => arm.joints[j].frictionloss.clone(),
        })
        .collect()
}

/// The unit body of entry `k`: `(m, h, J)`, one entry one and the rest zero.
fn unit_body(k: usize) -> (Poly, [Poly; 3], [[Poly; 3]; 3]) {
    let one = || Poly::constant(int(1));
    let mut m = Poly::default();
    let mut h: [Poly; 3] = Default::default();
    let mut j: [[Poly; 3]; 3] = Default::default();
    match k {
        0 => m = one(),
        1..=3 => h[k - 1] = one(),
        _ => {
            let (a, b) = [(0, 0), (0, 1), (1, 1), (0, 2), (1, 2), (2, 2)][k - 4];
            j[a][b] = one();
            j[b][a] = one();
        }
    }
    (m, h, j)
}

/// The payload's unit body of entry `k` (tool frame) moved into the last link's frame.
fn payload_unit(arm: &SpatialArmSpec, k: usize) -> (Poly, [Poly; 3], [[Poly; 3]; 3]) {
    let tool = tool_frame(arm);
    let value = |e: &crate::expr::Expr<Poly>| e.constant_term().cloned().unwrap_or_default();
    let r: [[Poly; 3]; 3] =
        core::array::from_fn(|a| core::array::from_fn(|b| value(&tool.r[a][b])));
    let p: [Poly; 3] = core::array::from_fn(|a| value(&tool.p[a]));
    let (m, h_t, j_t) = unit_body(k);
    let rh: [Poly; 3] = core::array::from_fn(|a| {
        (0..3).fold(Poly::default(), |acc, b| {
            acc + r[a][b].clone() * h_t[b].clone()
        })
    });
    let h = core::array::from_fn(|a| m.clone() * p[a].clone() + rh[a].clone());
    let p2 = p
        .iter()
        .fold(Poly::default(), |acc, x| acc + x.clone() * x.clone());
    let p_rh = (0..3).fold(Poly::default(), |acc, a| acc + p[a].clone() * rh[a].clone());
    let j = core::array::from_fn(|a| {
        core::array::from_fn(|b| {
            let mut e = Poly::default();
            for x in 0..3 {
                for y in 0..3 {
                    e = e + r[a][x].clone() * j_t[x][y].clone() * r[b][y].clone();
                }
            }
            e = e
                - m.clone() * p[a].clone() * p[b].clone()
                - p[a].clone() * rh[b].clone()
                - rh[a].clone() * p[b].clone();
            if a == b {
                e = e + m.clone() * p2.clone() + p_rh.clone() + p_rh.clone();
            }
            e
        })
    });
    (m, h, j)
}

/// The force and the moment about the origin that a body `(m, h, J)` needs in `motion`.
fn standard_load(
    p: &mut Program,
    motion: &Motion,
    (m, h, j): &(Poly, [Poly; 3], [[Poly; 3]; 3]),
) -> (V3, V3) {
    let m = p.poly(m);
    let h: V3 = core::array::from_fn(|k| p.poly(&h[k]));
    let j: [V3; 3] = core::array::from_fn(|a| core::array::from_fn(|b| p.poly(&j[a][b])));
    let times = |p: &mut Program, v: &V3| -> V3 {
        core::array::from_fn(|a| {
            let terms: Vec<Id> = (0..3).map(|b| p.mul(j[a][b], v[b])).collect();
            crate::programs::spatial::sum(p, &terms)
        })
    };
    let (w, dw, a) = (&motion.w, &motion.dw, &motion.a);
    let ma = scale(p, a, m);
    let dwh = cross(p, dw, &h);
    let wh = cross(p, w, &h);
    let wwh = cross(p, w, &wh);
    let f = add(p, &ma, &dwh);
    let force = add(p, &f, &wwh);
    let jdw = times(p, dw);
    let jw = times(p, w);
    let gyro = cross(p, w, &jw);
    let ha = cross(p, &h, a);
    let t = add(p, &jdw, &gyro);
    (force, add(p, &t, &ha))
}

/// The regressor's columns `columns` (indices into `parameters`), row-major outputs
/// `y{row}_{column}` (1-based, columns counted within `columns`).
#[must_use]
pub fn regressor(
    arm: &SpatialArmSpec,
    parameters: &[SpatialParameter],
    columns: &[usize],
) -> Method {
    let n = arm.joints.len();
    let mut p = Program::new();
    let joints: Vec<Joint> = (0..n).map(|j| Joint::new(&mut p, arm, j)).collect();
    let motions = motions(&mut p, arm, &joints, Terms::ALL);
    let zero = p.constant(int(0));
    let twists = unit_twists(&mut p, &joints, &motions);
    // Row `j` of a link-`i` column is joint `j`'s unit twist against the unit body's wrench,
    // both in link `i`'s axes: the twists are carried outward once per pair of joint and link
    // and shared by that link's ten columns, where carrying each column's wrench inward cost
    // a transformation per column and joint (the PUMA's base regressor 642 multiplications
    // that way, 464 this; the UR5's 652 and 407, the Panda's 833 and 751).
    let carrying = |p: &mut Program, link: usize, body: &(Poly, [Poly; 3], [[Poly; 3]; 3])| {
        let (force, moment) = standard_load(p, &motions[link], body);
        (0..n)
            .map(|j| match twists[link].get(j) {
                Some((w, v)) => {
                    let along = dot(p, v, &force);
                    let about = dot(p, w, &moment);
                    p.add(along, about)
                }
                None => zero,
            })
            .collect::<Vec<Id>>()
    };
    let on_row =
        |j: usize, x: Id| -> Vec<Id> { (0..n).map(|i| if i == j { x } else { zero }).collect() };
    let mut cols: Vec<Vec<Id>> = Vec::with_capacity(columns.len());
    for &c in columns {
        let col = match parameters[c].entry {
            Entry::Link(i, k) => carrying(&mut p, i, &unit_body(k)),
            Entry::Payload(k) => carrying(&mut p, n - 1, &payload_unit(arm, k)),
            Entry::Armature(j) => on_row(j, p.input(Input::Qdd(j))),
            Entry::Damping(j) => on_row(j, p.input(Input::Qd(j))),
            Entry::Frictionloss(j) => {
                let qd = p.input(Input::Qd(j));
                on_row(j, p.sign(qd))
            }
        };
        cols.push(col);
    }
    let mut outputs = Vec::with_capacity(n * columns.len());
    for i in 0..n {
        for (c, col) in cols.iter().enumerate() {
            outputs.push((format!("y{}_{}", i + 1, c + 1), col[i]));
        }
    }
    Method::new(p, outputs).described(&format!(
        "{DESCRIPTION}: once per standard parameter, that parameter one and the others zero (the \
         forces are linear in them), the motion of the links shared"
    ))
}

/// [`regressor`]'s entries as derivatives along the joints' virtual rates, four joints per
/// lane, in its outputs' order; `None` if [`pack`](crate::programs::packed::pack) cannot
/// carry the program.
///
/// Entry `(j, c)` is joint `j`'s unit twist against column `c`'s wrench, so row `j` is the
/// derivative along joint `j`'s virtual rate `u_j` of the virtual power `V_i . f + W_i . n`, the
/// wrench held and `(W_i, V_i)` the twist link `i` has when the joints move at rates `u`:
/// `W_i = Q_i W_{i-1} + z_i u_i`, `V_i = Q_i (V_{i-1} + W_{i-1} x pre_p) + W_i x r_i` (`+ z_i
/// u_i` for a slide). [`pack`](crate::programs::packed::pack) carries those derivatives as
/// four-lane values, so that carrying the twists outward and projecting each wrench on them
/// costs one vector operation per four joints.
#[must_use]
pub fn packed_regressor(
    arm: &SpatialArmSpec,
    parameters: &[SpatialParameter],
    columns: &[usize],
) -> Option<crate::programs::packed::Packed> {
    let n = arm.joints.len();
    let mut p = Program::new();
    let joints: Vec<Joint> = (0..n).map(|j| Joint::new(&mut p, arm, j)).collect();
    let motions = motions(&mut p, arm, &joints, Terms::ALL);
    let zero = p.constant(int(0));
    let mut twists: Vec<(V3, V3)> = Vec::with_capacity(n);
    for (i, joint) in joints.iter().enumerate() {
        let u = p.input(Input::Virtual(i));
        let r = motions[i].r;
        let (w, v) = match twists.last() {
            Some(twist) => across(&mut p, joint, twist),
            None => ([zero; 3], [zero; 3]),
        };
        let spin = scale(&mut p, &joint.z, u);
        let w = match joint.kind {
            JointKind::Revolute => add(&mut p, &w, &spin),
            JointKind::Prismatic => w,
        };
        let swing = cross(&mut p, &w, &r);
        let mut v = add(&mut p, &v, &swing);
        if joint.kind == JointKind::Prismatic {
            v = add(&mut p, &v, &spin);
        }
        twists.push((w, v));
    }
    let power = |p: &mut Program, link: usize, body: &(Poly, [Poly; 3], [[Poly; 3]; 3])| {
        let (force, moment) = standard_load(p, &motions[link], body);
        let (w, v) = &twists[link];
        let along = dot(p, v, &force);
        let about = dot(p, w, &moment);
        p.add(along, about)
    };
    let mut powers = Vec::with_capacity(columns.len());
    for &c in columns {
        let joint_term = |p: &mut Program, j: usize, x: Id| {
            let u = p.input(Input::Virtual(j));
            p.mul(u, x)
        };
        powers.push(match parameters[c].entry {
            Entry::Link(i, k) => power(&mut p, i, &unit_body(k)),
            Entry::Payload(k) => power(&mut p, n - 1, &payload_unit(arm, k)),
            Entry::Armature(j) => {
                let qdd = p.input(Input::Qdd(j));
                joint_term(&mut p, j, qdd)
            }
            Entry::Damping(j) => {
                let qd = p.input(Input::Qd(j));
                joint_term(&mut p, j, qd)
            }
            Entry::Frictionloss(j) => {
                let qd = p.input(Input::Qd(j));
                let sign = p.sign(qd);
                joint_term(&mut p, j, sign)
            }
        });
    }
    let directions: Vec<Input> = (0..n).map(Input::Virtual).collect();
    let mut pk = crate::programs::packed::pack(&p, &powers, &directions)?;
    // Column-major (power by power, joint by joint) to the regressor's rows.
    let by_column = std::mem::take(&mut pk.derivatives);
    pk.derivatives = (0..n)
        .flat_map(|j| (0..columns.len()).map(move |c| (j, c)))
        .map(|(j, c)| by_column[c * n + j])
        .collect();
    Some(pk)
}

/// Joint `j`'s unit twist in link `i`'s axes for every `j <= i` (`out[i][j]`): the angular
/// velocity and the velocity of link `i`'s origin when joint `j` alone moves at unit rate. A
/// wrench `(f, n)` on link `i` (moment about its origin) then loads joint `j` with `v . f + w .
/// n`, its power per unit rate.
fn unit_twists(p: &mut Program, joints: &[Joint], motions: &[Motion]) -> Vec<Vec<(V3, V3)>> {
    let zero = p.constant(int(0));
    let mut out: Vec<Vec<(V3, V3)>> = Vec::with_capacity(joints.len());
    for (i, joint) in joints.iter().enumerate() {
        let r = motions[i].r;
        let mut row = Vec::with_capacity(i + 1);
        if i > 0 {
            for twist in out[i - 1].clone() {
                let (w, v) = across(p, joint, &twist);
                let swing = cross(p, &w, &r);
                row.push((w, add(p, &v, &swing)));
            }
        }
        row.push(match joint.kind {
            JointKind::Revolute => (joint.z, cross(p, &joint.z, &r)),
            JointKind::Prismatic => ([zero; 3], joint.z),
        });
        out.push(row);
    }
    out
}

/// A twist of link `i - 1` `(w, v)` (angular velocity, velocity of its origin) carried across
/// joint `i`'s fixed part and rotation: the same motion, in link `i`'s axes, with `v` at the
/// joint's axis point `A_i`. Moving `v` on to link `i`'s origin (`+ w x r_i`) is left to the
/// caller, which may first add the joint's own rate.
fn across(p: &mut Program, joint: &Joint, (w, v): &(V3, V3)) -> (V3, V3) {
    let lever = cross(p, w, &joint.pre.p);
    let at_axis = add(p, v, &lever);
    (joint.inward(p, w), joint.inward(p, &at_axis))
}
