//! Exact kinematics of a spatial arm: each link's frame as a rotation and a position whose
//! entries are trigonometric polynomials in the joint angles (and polynomials in the slides),
//! multiplied out base to tip; the centres of mass, the potential energy and its gradient, the
//! gravity torques.

use super::spec::{FixedAngle, SpatialArmSpec, SpatialBody, SpatialGeometry, SpatialJointSpec};
use crate::algebra::expr::{Expr, Var};
use crate::algebra::poly::Poly;
use crate::algebra::ring::int;
use crate::algebra::trig::{Angle, Trig};
use crate::mechanics::planar::JointKind;

type E = Expr<Poly>;

/// A rigid transformation with exact entries: `x -> r x + p`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Frame {
    /// Rotation, row-major.
    pub r: [[E; 3]; 3],
    /// Translation.
    pub p: [E; 3],
}

fn constant(c: &Poly) -> E {
    E::constant(c.clone())
}

fn one() -> Poly {
    Poly::constant(int(1))
}

impl Frame {
    /// The identity.
    #[must_use]
    pub fn identity() -> Self {
        Self::from_rotation(&[
            [one(), Poly::default(), Poly::default()],
            [Poly::default(), one(), Poly::default()],
            [Poly::default(), Poly::default(), one()],
        ])
    }

    /// A constant rotation.
    #[must_use]
    pub fn from_rotation(r: &[[Poly; 3]; 3]) -> Self {
        Self {
            r: core::array::from_fn(|i| core::array::from_fn(|j| constant(&r[i][j]))),
            p: core::array::from_fn(|_| E::zero()),
        }
    }

    /// A translation by exact expressions.
    #[must_use]
    pub fn translation(p: [E; 3]) -> Self {
        Self {
            p,
            ..Self::identity()
        }
    }

    /// `self * other`: `r = r1 r2`, `p = r1 p2 + p1`.
    #[must_use]
    pub fn mul(&self, other: &Self) -> Self {
        self.mul_within(other, usize::MAX)
            .unwrap_or_else(|| unreachable!("no budget"))
    }

    /// `self * other`, or `None` as soon as the entries computed so far exceed `budget` (see
    /// [`EXPANSION_BUDGET`]).
    #[must_use]
    pub fn mul_within(&self, other: &Self, budget: usize) -> Option<Self> {
        let mut spent = 0;
        let mut entry = |e: E| {
            spent += size(&e);
            (spent <= budget).then_some(e)
        };
        let mut r: [[E; 3]; 3] = Default::default();
        for (i, row) in r.iter_mut().enumerate() {
            for (j, out) in row.iter_mut().enumerate() {
                let mut e = E::zero();
                for k in 0..3 {
                    e.add_product(&self.r[i][k], &other.r[k][j]);
                }
                *out = entry(e)?;
            }
        }
        let mut p: [E; 3] = Default::default();
        for (i, out) in p.iter_mut().enumerate() {
            let mut e = self.p[i].clone();
            for k in 0..3 {
                e.add_product(&self.r[i][k], &other.p[k]);
            }
            *out = entry(e)?;
        }
        Some(Self { r, p })
    }

    /// `r v`.
    #[must_use]
    pub fn rotate(&self, v: &[E; 3]) -> [E; 3] {
        core::array::from_fn(|i| {
            let mut e = E::zero();
            for (r, x) in self.r[i].iter().zip(v) {
                e.add_product(r, x);
            }
            e
        })
    }

    /// `r v + p`.
    #[must_use]
    pub fn apply(&self, v: &[E; 3]) -> [E; 3] {
        let mut out = self.rotate(v);
        for (o, p) in out.iter_mut().zip(&self.p) {
            o.add_assign(p);
        }
        out
    }
}

/// `Rx(angle)`, `Ry(angle)`, `Rz(angle)` for a constant angle.
fn elementary(axis: usize, angle: &FixedAngle) -> Frame {
    let (c, s) = angle.cos_sin();
    let z = Poly::default;
    let r = match axis {
        0 => [[one(), z(), z()], [z(), c.clone(), -s.clone()], [z(), s, c]],
        1 => [[c.clone(), z(), s.clone()], [z(), one(), z()], [-s, z(), c]],
        _ => [[c.clone(), -s.clone(), z()], [s, c, z()], [z(), z(), one()]],
    };
    Frame::from_rotation(&r)
}

fn shift(x: &Poly, y: &Poly, z: &Poly) -> Frame {
    Frame::translation([constant(x), constant(y), constant(z)])
}

fn rpy(a: &[FixedAngle; 3]) -> Frame {
    elementary(2, &a[2])
        .mul(&elementary(1, &a[1]))
        .mul(&elementary(0, &a[0]))
}

/// The rotation by `q_j` about the unit axis `u` (exact entries): `c I + s [u]x + (1 - c) u u^T`.
fn turn(u: &[Poly; 3], j: usize) -> Frame {
    let mut k = vec![0; j + 1];
    k[j] = 1;
    let angle = Angle::new(k);
    let c = E::cos(one(), angle.clone());
    let s = E::sin(one(), angle);
    let one_minus_c = constant(&one()).sub(&c);
    let cross = [
        [Poly::default(), -u[2].clone(), u[1].clone()],
        [u[2].clone(), Poly::default(), -u[0].clone()],
        [-u[1].clone(), u[0].clone(), Poly::default()],
    ];
    let r = core::array::from_fn(|a| {
        core::array::from_fn(|b| {
            let mut e = one_minus_c.scale_by(&(u[a].clone() * u[b].clone()));
            e.add_assign(&s.scale_by(&cross[a][b]));
            if a == b {
                e.add_assign(&c);
            }
            e
        })
    });
    Frame {
        r,
        p: core::array::from_fn(|_| E::zero()),
    }
}

/// The slide by `q_j` along the unit axis `u`.
fn slide(u: &[Poly; 3], j: usize) -> Frame {
    let q = E::var(Var::Q(j));
    Frame::translation(core::array::from_fn(|i| q.scale_by(&u[i])))
}

/// The three parts of joint `j`'s transformation `pre * motion(q_j) * post`: where the axis is
/// (`pre`), the motion about or along the axis `u` in `pre`'s frame, and what follows it.
#[must_use]
pub fn joint_parts(joint: &SpatialJointSpec) -> (Frame, [Poly; 3], Frame) {
    let zero = Poly::default;
    let z_axis = [zero(), zero(), one()];
    let revolute = joint.kind == JointKind::Revolute;
    match &joint.geometry {
        SpatialGeometry::Dh { a, alpha, d, theta } => {
            let twist = shift(a, &zero(), &zero()).mul(&elementary(0, alpha));
            if revolute {
                (
                    elementary(2, theta),
                    z_axis,
                    shift(&zero(), &zero(), d).mul(&twist),
                )
            } else {
                (
                    elementary(2, theta).mul(&shift(&zero(), &zero(), d)),
                    z_axis,
                    twist,
                )
            }
        }
        SpatialGeometry::Mdh { a, alpha, d, theta } => {
            let pre = elementary(0, alpha)
                .mul(&shift(a, &zero(), &zero()))
                .mul(&elementary(2, theta));
            if revolute {
                (pre, z_axis, shift(&zero(), &zero(), d))
            } else {
                (
                    pre.mul(&shift(&zero(), &zero(), d)),
                    z_axis,
                    Frame::identity(),
                )
            }
        }
        SpatialGeometry::Urdf {
            xyz,
            rpy: angles,
            axis,
        } => (
            shift(&xyz[0], &xyz[1], &xyz[2]).mul(&rpy(angles)),
            axis.clone(),
            Frame::identity(),
        ),
    }
}

/// The motion of joint `j` about or along `u`.
#[must_use]
pub fn motion(kind: JointKind, u: &[Poly; 3], j: usize) -> Frame {
    match kind {
        JointKind::Revolute => turn(u, j),
        JointKind::Prismatic => slide(u, j),
    }
}

/// The tool frame in the last link's frame.
#[must_use]
pub fn tool_frame(arm: &SpatialArmSpec) -> Frame {
    shift(&arm.tool_xyz[0], &arm.tool_xyz[1], &arm.tool_xyz[2]).mul(&rpy(&arm.tool_rpy))
}

/// The bodies link `i` carries, in its frame: its own, and on the last link the payload moved
/// from the tool frame (centre `R c + p`, tensor `R I R^T`, exact).
#[must_use]
pub fn link_bodies(arm: &SpatialArmSpec, i: usize) -> Vec<SpatialBody> {
    let mut bodies = vec![SpatialBody::of_link(&arm.joints[i])];
    if let Some(payload) = arm.payload.as_ref().filter(|_| i + 1 == arm.joints.len()) {
        bodies.push(payload_in_last_link(arm, payload));
    }
    bodies
}

fn payload_in_last_link(arm: &SpatialArmSpec, payload: &SpatialBody) -> SpatialBody {
    let tool = tool_frame(arm);
    let value = |e: &E| e.constant_term().cloned().unwrap_or_default();
    let r: [[Poly; 3]; 3] =
        core::array::from_fn(|a| core::array::from_fn(|b| value(&tool.r[a][b])));
    let com = core::array::from_fn(|a| {
        (0..3).fold(value(&tool.p[a]), |acc, b| {
            acc + r[a][b].clone() * payload.com[b].clone()
        })
    });
    let [xx, yy, zz, xy, xz, yz] = payload.inertia.clone();
    let tensor = [
        [xx, xy.clone(), xz.clone()],
        [xy, yy, yz.clone()],
        [xz, yz, zz],
    ];
    let turned = |a: usize, b: usize| -> Poly {
        let mut sum = Poly::default();
        for k in 0..3 {
            for l in 0..3 {
                sum = sum + r[a][k].clone() * tensor[k][l].clone() * r[b][l].clone();
            }
        }
        sum
    };
    SpatialBody {
        mass: payload.mass.clone(),
        com,
        inertia: [
            turned(0, 0),
            turned(1, 1),
            turned(2, 2),
            turned(0, 1),
            turned(0, 2),
            turned(1, 2),
        ],
    }
}

/// The exact kinematics of an arm.
#[derive(Clone, Debug)]
pub struct SpatialKinematics {
    /// Each link's frame in the base frame.
    pub links: Vec<Frame>,
    /// The tool frame.
    pub tool: Frame,
    /// Each joint's axis in the base frame: a point on it and its unit direction.
    pub axes: Vec<([E; 3], [E; 3])>,
    /// Each link's centre of mass in the base frame.
    pub centres: Vec<[E; 3]>,
    /// The potential energy `-sum m g . c`.
    pub potential_energy: E,
    /// The gravity torques `dV/dq`.
    pub gravity: Vec<E>,
}

/// How large (terms, counting each coefficient's monomials in named constants and run-time
/// parameters) one multiplied-out frame or the potential energy may grow before the engine
/// stops expanding. Right-angle geometry stays below it (the PUMA 560's tool frame is 263, the
/// Panda's 2 500); generic twists or rotated URDF origins multiply the size several times a
/// joint, and only the product of the joints' transformations stays linear in their number.
/// Deriving an arm just under the budget takes under a second.
pub const EXPANSION_BUDGET: usize = 4_000;

/// The size of an expression for [`EXPANSION_BUDGET`]: its terms and, in each coefficient, the
/// monomials of named constants and run-time parameters (where generic twists grow).
fn size(e: &E) -> usize {
    e.terms().map(|(_, _, c)| c.terms().count().max(1)).sum()
}

impl SpatialKinematics {
    /// Multiplies the arm out, however many terms that takes.
    #[must_use]
    pub fn derive(arm: &SpatialArmSpec) -> Self {
        Self::chain(arm, true, usize::MAX).unwrap_or_else(|| unreachable!("no budget"))
    }

    /// Multiplies the arm out unless a frame, the potential energy or a gravity torque grows
    /// past `budget` terms.
    #[must_use]
    pub fn derive_within(arm: &SpatialArmSpec, budget: usize) -> Option<Self> {
        Self::chain(arm, true, budget)
    }

    /// The arm at `q = 0` (every frame constant): what deciding the inverse kinematics' class
    /// needs, cheap whatever the geometry.
    #[must_use]
    pub fn home(arm: &SpatialArmSpec) -> Self {
        Self::chain(arm, false, usize::MAX).unwrap_or_else(|| unreachable!("no budget"))
    }

    fn chain(arm: &SpatialArmSpec, moving: bool, budget: usize) -> Option<Self> {
        let mut frame = Frame::identity();
        let (mut links, mut axes, mut centres) = (Vec::new(), Vec::new(), Vec::new());
        let mut potential = E::zero();
        for (j, joint) in arm.joints.iter().enumerate() {
            let (pre, u, post) = joint_parts(joint);
            let at_axis = frame.mul_within(&pre, budget)?;
            let u_expr: [E; 3] = core::array::from_fn(|i| constant(&u[i]));
            axes.push((at_axis.p.clone(), at_axis.rotate(&u_expr)));
            let moved = if moving {
                at_axis.mul_within(&motion(joint.kind, &u, j), budget)?
            } else {
                at_axis
            };
            frame = moved.mul_within(&post, budget)?;
            let mut centre = None;
            for body in link_bodies(arm, j) {
                let com: [E; 3] = core::array::from_fn(|i| constant(&body.com[i]));
                let c = frame.apply(&com);
                for (g, ci) in arm.gravity.iter().zip(&c) {
                    potential.sub_assign(&ci.scale_by(&(body.mass.clone() * g.clone())));
                }
                centre.get_or_insert(c);
            }
            if size(&potential) > budget {
                return None;
            }
            centres.push(centre.unwrap_or_default());
            links.push(frame.clone());
        }
        let tool = frame.mul_within(&tool_frame(arm), budget)?;
        // The joint springs' energy, stiffness (q - springref)^2 / 2: the potential is theirs
        // and gravity's, and g = dV/dq holds the springs' torques.
        for (j, joint) in arm
            .joints
            .iter()
            .enumerate()
            .filter(|(_, j)| moving && j.sprung())
        {
            let stretch = E::var(Var::Q(j)).sub(&constant(&joint.springref));
            let energy = stretch
                .mul(&stretch)
                .scale_by(&joint.stiffness)
                .scale(&crate::algebra::ring::ratio(1, 2));
            potential.add_assign(&energy);
        }
        let gravity = (0..arm.joints.len()).map(|i| potential.diff_q(i)).collect();
        Some(Self {
            links,
            tool,
            axes,
            centres,
            potential_energy: potential,
            gravity,
        })
    }
}

/// The value of `e` at `q = 0`: cosines 1, sines 0, slides 0.
#[must_use]
pub fn at_zero(e: &E) -> Poly {
    let mut out = Poly::default();
    for (m, t, c) in e.terms() {
        if m.degree() == 0 && !matches!(t, Trig::Sin(_)) {
            out = out + c.clone();
        }
    }
    out
}
