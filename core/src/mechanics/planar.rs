//! Lagrangian mechanics of a planar serial arm, following the paper's route: velocities of
//! each centre of mass and link angular velocities, kinetic energy (translation of the centre
//! of mass plus rotation about it), potential energy of the centres of mass. Then M is the
//! Hessian of T in the rates, g = dV/dq, C comes from Christoffel symbols of M and c = C qd:
//! the same exact functions Lagrange's equation gives (`Dynamics::lagrange_torques` expands
//! that equation itself, and the tests assert the two equal), without its costliest step.

use std::fmt;

use crate::expr::{Expr, Monomial, Var};
use crate::poly::{Param, Poly};
use crate::ring::{int, ratio, Coefficient, Rational};
use crate::trig::Angle;

/// The kind of a link's joint.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum JointKind {
    /// A hinge: `q_i` is the link's angle relative to the previous link.
    #[default]
    Revolute,
    /// A slider along the previous link's direction (for the first link, +x of the base):
    /// `q_i` is the displacement; the link does not turn.
    Prismatic,
}

/// One link and its joint: exact parameters (or polynomials in run-time parameters).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkSpec<C = Rational> {
    /// Joint-to-joint length.
    pub length: C,
    /// Mass.
    pub mass: C,
    /// Moment of inertia about the centre of mass.
    pub inertia: C,
    /// The centre of mass in the link's frame: `.0` along the link from its own joint toward
    /// the next, `.1` perpendicular to it, counter-clockwise.
    pub com: (C, C),
    /// Reflected rotor inertia at this link's joint (MuJoCo's `armature`): kinetic energy
    /// `armature qd_i^2 / 2`, so it adds to `M_ii`.
    pub armature: C,
    /// Viscous friction at this link's joint: torque `damping qd_i`.
    pub damping: C,
    /// Coulomb friction at this link's joint: torque `frictionloss sign(qd_i)`.
    pub frictionloss: C,
    /// The joint's kind.
    pub joint: JointKind,
    /// The joint's range `(lower, upper)`, if given: kinematics only, never the dynamics.
    pub range: Option<(Rational, Rational)>,
}

impl<C: Coefficient> LinkSpec<C> {
    /// A uniform rod: inertia `m l^2 / 12`, centre of mass at `(l / 2, 0)`, no armature, no
    /// friction.
    #[must_use]
    pub fn rod(length: C, mass: C) -> Self {
        let zero = C::from_rational(int(0));
        Self {
            inertia: (mass.clone() * length.clone() * length.clone()).scale(&ratio(1, 12)),
            com: (length.scale(&ratio(1, 2)), zero.clone()),
            length,
            mass,
            armature: zero.clone(),
            damping: zero.clone(),
            frictionloss: zero,
            joint: JointKind::Revolute,
            range: None,
        }
    }
}

/// A body rigidly held at the tip of the last link: a payload, a tool, a gripper.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PayloadSpec<C = Rational> {
    /// Mass.
    pub mass: C,
    /// Moment of inertia about its own centre of mass.
    pub inertia: C,
    /// Its centre of mass relative to the tip, in the last link's frame.
    pub com: (C, C),
}

/// A planar serial arm of revolute links, base first, with gravity of magnitude `gravity`
/// along -y and perhaps a payload at the tip.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ArmSpec<C = Rational> {
    /// The links, base first.
    pub links: Vec<LinkSpec<C>>,
    /// Magnitude of gravity, along -y.
    pub gravity: C,
    /// The body held at the tip, if any.
    pub payload: Option<PayloadSpec<C>>,
}

impl ArmSpec<Rational> {
    /// `n` equal uniform rods of unit length and mass, no gravity: the paper's equal links.
    #[must_use]
    pub fn paper(n: usize) -> Self {
        Self {
            links: vec![LinkSpec::rod(int(1), int(1)); n],
            gravity: int(0),
            payload: None,
        }
    }
}

impl ArmSpec<Rational> {
    /// The same arm with every value a run-time parameter, named `v0, v1, ...` in the order
    /// link by link (length, mass, inertia, com x, com y, armature, damping, frictionloss),
    /// then gravity, then the payload's; and each parameter's value. The derivation over it,
    /// evaluated at those values, must give the literal arm's numbers: a check of the
    /// polynomial path against the rational one.
    #[must_use]
    pub fn parameterised(&self) -> (ArmSpec<Poly>, Vec<(Param, Rational)>) {
        let mut values = Vec::new();
        let mut param = |r: &Rational| {
            let p = Param::new(&format!("v{}", values.len()));
            values.push((p.clone(), r.clone()));
            Poly::param(p)
        };
        let links = self
            .links
            .iter()
            .map(|l| LinkSpec {
                length: param(&l.length),
                mass: param(&l.mass),
                inertia: param(&l.inertia),
                com: (param(&l.com.0), param(&l.com.1)),
                armature: param(&l.armature),
                damping: param(&l.damping),
                frictionloss: param(&l.frictionloss),
                joint: l.joint,
                range: l.range.clone(),
            })
            .collect();
        let gravity = param(&self.gravity);
        let payload = self.payload.as_ref().map(|p| PayloadSpec {
            mass: param(&p.mass),
            inertia: param(&p.inertia),
            com: (param(&p.com.0), param(&p.com.1)),
        });
        (
            ArmSpec {
                links,
                gravity,
                payload,
            },
            values,
        )
    }
}

/// The equations of motion `tau = M(q) qdd + c(q, qd) + g(q)`, exact (joint friction, which no
/// Lagrangian holds, is added by the generated methods from the arm's `damping` and
/// `frictionloss`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dynamics<C = Rational> {
    /// Number of joints.
    pub n: usize,
    /// Kinetic energy T(q, qd).
    pub kinetic_energy: Expr<C>,
    /// Potential energy V(q), zero at y = 0.
    pub potential_energy: Expr<C>,
    /// The mass matrix, row-major.
    pub mass_matrix: Vec<Vec<Expr<C>>>,
    /// The velocity-product torques c(q, qd).
    pub coriolis: Vec<Expr<C>>,
    /// The gravity torques g(q) = dV/dq.
    pub gravity: Vec<Expr<C>>,
}

/// Forward kinematics and statics of the arm, exact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Kinematics<C = Rational> {
    /// Number of joints.
    pub n: usize,
    /// Each link's frame origin `(x, y)` (its joint; for a prismatic joint the slid carriage,
    /// so joint 1 is at the origin unless it is prismatic), then the tip last (n + 1 entries).
    pub points: Vec<(Expr<C>, Expr<C>)>,
    /// The absolute angle of the last link.
    pub tip_angle: Angle,
    /// The 3 x n Jacobian, row-major: d/dt of tip x, tip y, last angle.
    pub jacobian: Vec<Vec<Expr<C>>>,
    /// `r^2 = x^2 + y^2` of the tip: independent of q1.
    pub radius_squared: Expr<C>,
}

fn rate(j: usize) -> Var {
    Var::Qd(j)
}

/// Absolute angle of link `i` (0-based): the sum of the revolute joints' angles up to it,
/// `q_1 + ... + q_{i+1}` when all are revolute (a prismatic joint does not turn its link).
fn link_angle<C>(arm: &ArmSpec<C>, i: usize) -> Angle {
    Angle::new(
        arm.links[..=i]
            .iter()
            .map(|l| i32::from(l.joint == JointKind::Revolute))
            .collect(),
    )
}

impl<C> ArmSpec<C> {
    /// Whether every joint is revolute (the paper's arms).
    #[must_use]
    pub fn all_revolute(&self) -> bool {
        self.links.iter().all(|l| l.joint == JointKind::Revolute)
    }

    /// The same arm with joint `i` prismatic where bit `i` of `pattern` is set: the tests'
    /// way to run one check over every mix of joint kinds.
    #[cfg(test)]
    pub(crate) fn with_prismatic(mut self, pattern: u32) -> Self {
        for (i, l) in self.links.iter_mut().enumerate() {
            if pattern >> i & 1 == 1 {
                l.joint = JointKind::Prismatic;
            }
        }
        self
    }
}

/// `(x, y)` of the point `at` (in link `i`'s frame, from its own frame's origin) of link `i`:
/// the earlier links full length, and each prismatic joint up to `i` sliding its link by `q_k`
/// along the link's direction.
fn point_on_link<C: Coefficient>(arm: &ArmSpec<C>, i: usize, at: &(C, C)) -> (Expr<C>, Expr<C>) {
    let mut x = Expr::zero();
    let mut y = Expr::zero();
    for (j, link) in arm.links.iter().enumerate().take(i) {
        x = x.add(&Expr::cos(link.length.clone(), link_angle(arm, j)));
        y = y.add(&Expr::sin(link.length.clone(), link_angle(arm, j)));
    }
    let one = C::from_rational(int(1));
    for (k, link) in arm.links.iter().enumerate().take(i + 1) {
        if link.joint == JointKind::Prismatic {
            let slide = Var::Q(k);
            x = x.add(&Expr::cos(one.clone(), link_angle(arm, k)).mul_var(slide));
            y = y.add(&Expr::sin(one.clone(), link_angle(arm, k)).mul_var(slide));
        }
    }
    // R(phi_i) (a, b) = (a cos - b sin, a sin + b cos)
    let (a, b) = at;
    let angle = link_angle(arm, i);
    x = x
        .add(&Expr::cos(a.clone(), angle.clone()))
        .sub(&Expr::sin(b.clone(), angle.clone()));
    y = y
        .add(&Expr::sin(a.clone(), angle.clone()))
        .add(&Expr::cos(b.clone(), angle));
    (x, y)
}

/// Each body: (link, centre of mass in the link's frame, mass, inertia about the centre); the
/// payload is a body of the last link.
fn bodies<C: Coefficient>(arm: &ArmSpec<C>) -> Vec<(usize, (C, C), &C, &C)> {
    let n = arm.links.len();
    let mut bodies: Vec<(usize, (C, C), &C, &C)> = arm
        .links
        .iter()
        .enumerate()
        .map(|(i, l)| (i, l.com.clone(), &l.mass, &l.inertia))
        .collect();
    if let (Some(p), Some(last)) = (&arm.payload, arm.links.last()) {
        let at = (last.length.clone() + p.com.0.clone(), p.com.1.clone());
        bodies.push((n - 1, at, &p.mass, &p.inertia));
    }
    bodies
}

/// A rigid body of a link in the parameters its energies are linear in (the standard
/// parameters of identification): mass `m`, first moment `m c` in the link's frame, and moment
/// of inertia about the link's joint `I + m |c|^2`.
#[derive(Clone, Debug, PartialEq)]
pub struct Body<C = Rational> {
    /// The link (0-based) the body moves with.
    pub link: usize,
    /// Mass.
    pub mass: C,
    /// First moment `(m cx, m cy)` in the link's frame.
    pub first_moment: (C, C),
    /// Moment of inertia about the link's joint.
    pub joint_inertia: C,
}

/// The arm's bodies (links, then the payload on the last link) in standard parameters.
#[must_use]
pub fn standard_bodies<C: Coefficient>(arm: &ArmSpec<C>) -> Vec<Body<C>> {
    bodies(arm)
        .into_iter()
        .map(|(link, (cx, cy), mass, inertia)| Body {
            link,
            mass: mass.clone(),
            first_moment: (mass.clone() * cx.clone(), mass.clone() * cy.clone()),
            joint_inertia: mass.clone() * (cx.clone() * cx.clone() + cy.clone() * cy)
                + inertia.clone(),
        })
        .collect()
}

/// The potential energy of the bodies: `g (m y_joint + m cx sin theta + m cy cos theta)` each.
fn potential_energy<C: Coefficient>(arm: &ArmSpec<C>, bodies: &[Body<C>]) -> Expr<C> {
    let mut potential = Expr::zero();
    let zero = C::from_rational(int(0));
    for body in bodies {
        let i = body.link;
        let (_, y_joint) = point_on_link(arm, i, &(zero.clone(), zero.clone()));
        let (mx, my) = &body.first_moment;
        let y = y_joint
            .scale_by(&body.mass)
            .add(&Expr::sin(mx.clone(), link_angle(arm, i)))
            .add(&Expr::cos(my.clone(), link_angle(arm, i)));
        potential.add_assign(&y.scale_by(&arm.gravity));
    }
    potential
}

/// The products `omega_a omega_b` of the links' absolute rates, each built once and shared by
/// every energy derived with the same cache.
#[derive(Clone, Debug, Default)]
pub struct RateProducts<C = Rational> {
    products: std::collections::BTreeMap<(usize, usize), Expr<C>>,
}

impl<C: Coefficient> RateProducts<C> {
    /// An empty cache.
    #[must_use]
    pub fn new() -> Self {
        Self {
            products: std::collections::BTreeMap::new(),
        }
    }

    /// `omega_a omega_b` (`a >= b`), `omega_a = qd_1 + ... + qd_(a+1)`.
    pub(crate) fn product(&mut self, a: usize, b: usize) -> &Expr<C> {
        self.products.entry((a, b)).or_insert_with(|| {
            let omega = |k: usize| {
                let mut w = Expr::zero();
                for j in 0..=k {
                    w.add_assign(&Expr::var(rate(j)));
                }
                w
            };
            omega(a).mul(&omega(b))
        })
    }
}

/// The kinetic energy, built in its pairwise form: a sum over pairs of links `a >= b` of
/// `omega_a omega_b` times `A cos(theta_a - theta_b) - B sin(theta_a - theta_b)`, `A` and `B`
/// summed over the bodies ([`metric`]). Squaring the velocity's x and y expressions
/// gives the same canonical expression (checked in the tests) but creates every
/// `cos(theta_a + theta_b)` term only to cancel it, and dominated the derive's time.
fn kinetic_energy<C: Coefficient>(
    arm: &ArmSpec<C>,
    bodies: &[Body<C>],
    rates: &mut RateProducts<C>,
) -> Expr<C> {
    if !arm.all_revolute() {
        return kinetic_energy_of_velocities(arm, bodies);
    }
    let n = arm.links.len();
    let metric::Pairs { diag, cross } = metric::pairs(arm, bodies);
    let half = ratio(1, 2);
    let mut kinetic = Expr::zero();
    for a in 0..n {
        if !diag[a].is_zero() {
            let w = rates.product(a, a);
            kinetic.add_assign(&w.scale_by(&diag[a]).scale(&half));
        }
        for (b, (ca, cb)) in cross[a].iter().enumerate() {
            if ca.is_zero() && cb.is_zero() {
                continue;
            }
            let angle = Angle::range(b + 1, a + 1);
            let trig = Expr::cos(ca.clone(), angle.clone()).sub(&Expr::sin(cb.clone(), angle));
            kinetic.add_product(rates.product(a, b), &trig);
        }
    }
    // The rotors: armature times the joint's own rate squared.
    for (i, link) in arm.links.iter().enumerate() {
        if !link.armature.is_zero() {
            let qd = Expr::var(rate(i));
            kinetic.add_assign(&qd.mul(&qd).scale_by(&link.armature).scale(&half));
        }
    }
    kinetic
}

/// The kinetic energy from each body's frame-origin velocity `v` (the chain rule on its
/// position), for any mix of joints: `m |v|^2 / 2 + omega v . perp(R h) + J omega^2 / 2` per
/// body, with `h` its first moment and `J` its inertia about the frame origin, so it stays
/// linear in the standard parameters; plus the rotors. The pairwise form of the revolute arms
/// rests on every link length being constant.
fn kinetic_energy_of_velocities<C: Coefficient>(arm: &ArmSpec<C>, bodies: &[Body<C>]) -> Expr<C> {
    let n = arm.links.len();
    let half = ratio(1, 2);
    let zero = || C::from_rational(int(0));
    let one = C::from_rational(int(1));
    let mut kinetic = Expr::zero();
    for body in bodies {
        let i = body.link;
        let (x, y) = point_on_link(arm, i, &(zero(), zero()));
        let (vx, vy) = (x.dt(n), y.dt(n));
        let mut omega = Expr::zero();
        for (j, link) in arm.links.iter().enumerate().take(i + 1) {
            if link.joint == JointKind::Revolute {
                omega.add_assign(&Expr::var(rate(j)));
            }
        }
        let angle = link_angle(arm, i);
        let (cu, su) = (
            Expr::cos(one.clone(), angle.clone()),
            Expr::sin(one.clone(), angle),
        );
        // Each product only for a body that has the parameter: the identification derives
        // one body per standard parameter, all but one of them zero.
        if !body.mass.is_zero() {
            let v2 = vx.mul(&vx).add(&vy.mul(&vy));
            kinetic.add_assign(&v2.scale_by(&body.mass).scale(&half));
        }
        let (hx, hy) = &body.first_moment;
        // v . perp(R h) = hx v . perp(u) - hy v . u
        if !hx.is_zero() {
            let across = vy.mul(&cu).sub(&vx.mul(&su));
            kinetic.add_assign(&omega.mul(&across.scale_by(hx)));
        }
        if !hy.is_zero() {
            let along = vx.mul(&cu).add(&vy.mul(&su));
            kinetic.sub_assign(&omega.mul(&along.scale_by(hy)));
        }
        if !body.joint_inertia.is_zero() {
            kinetic.add_assign(&omega.mul(&omega).scale_by(&body.joint_inertia).scale(&half));
        }
    }
    for (i, link) in arm.links.iter().enumerate() {
        if !link.armature.is_zero() {
            let qd = Expr::var(rate(i));
            kinetic.add_assign(&qd.mul(&qd).scale_by(&link.armature).scale(&half));
        }
    }
    kinetic
}

/// The end of link `i` in its own frame.
fn link_end<C: Coefficient>(link: &LinkSpec<C>) -> (C, C) {
    (link.length.clone(), C::from_rational(int(0)))
}

impl<C: Coefficient> Kinematics<C> {
    /// Derives the forward kinematics.
    #[must_use]
    pub fn derive(arm: &ArmSpec<C>) -> Self {
        let n = arm.links.len();
        let zero = || C::from_rational(int(0));
        // Each link's frame origin (a prismatic joint's carriage), then the tip.
        let mut points: Vec<_> = (0..n)
            .map(|i| point_on_link(arm, i, &(zero(), zero())))
            .collect();
        if let Some(last) = arm.links.last() {
            points.push(point_on_link(arm, n - 1, &link_end(last)));
        } else {
            points.push((Expr::zero(), Expr::zero()));
        }
        let (x, y) = points[n].clone();
        let jacobian = vec![
            (0..n).map(|j| x.diff_q(j)).collect(),
            (0..n).map(|j| y.diff_q(j)).collect(),
            arm.links
                .iter()
                .map(|l| match l.joint {
                    JointKind::Revolute => Expr::constant(C::from_rational(int(1))),
                    JointKind::Prismatic => Expr::zero(),
                })
                .collect(),
        ];
        let radius_squared = x.mul(&x).add(&y.mul(&y));
        Self {
            n,
            points,
            tip_angle: if n == 0 {
                Angle::new(Vec::new())
            } else {
                link_angle(arm, n - 1)
            },
            jacobian,
            radius_squared,
        }
    }
}

impl<C: Coefficient> Dynamics<C> {
    /// Derives the equations of motion by Lagrange's equation.
    #[must_use]
    pub fn derive(arm: &ArmSpec<C>) -> Self {
        Self::of_bodies(arm, &standard_bodies(arm))
    }

    /// The kinetic and potential energies of the arm's geometry (lengths, armature, gravity)
    /// carrying `bodies`: linear in the bodies' standard parameters.
    #[must_use]
    pub fn energies(
        arm: &ArmSpec<C>,
        bodies: &[Body<C>],
        rates: &mut RateProducts<C>,
    ) -> (Expr<C>, Expr<C>) {
        (
            kinetic_energy(arm, bodies, rates),
            potential_energy(arm, bodies),
        )
    }

    /// The equations of motion of the arm's links and joints (lengths, armature) carrying
    /// `bodies` in standard parameters instead of its own links' masses. The energies are
    /// linear in the bodies' parameters, which is what the regressor uses.
    #[must_use]
    pub fn of_bodies(arm: &ArmSpec<C>, bodies: &[Body<C>]) -> Self {
        let n = arm.links.len();
        let mut rates = RateProducts::new();
        let kinetic = kinetic_energy(arm, bodies, &mut rates);
        let potential = potential_energy(arm, bodies);
        // M as the Hessian of T in the rates, g = dV/dq, and the velocity terms from the
        // momenta p = dT/dqd: the same exact functions Lagrange's equation gives (checked
        // against it by `lagrange_torques`), without expanding d/dt dL/dqd, the costliest step.
        // For arms whose joints all turn, M and c are summed from the metric in absolute
        // angles instead (small expressions per pair of links): the same expressions at a
        // fraction of the cost for long arms.
        let (mass_matrix, coriolis) = if arm.all_revolute() {
            let pairs = metric::pairs(arm, bodies);
            (pairs.mass_matrix(arm), pairs.coriolis(&mut rates))
        } else {
            let p: Vec<Expr<C>> = (0..n).map(|i| kinetic.diff_var(rate(i))).collect();
            let m: Vec<Vec<Expr<C>>> = (0..n)
                .map(|i| (0..n).map(|j| p[i].diff_var(rate(j))).collect())
                .collect();
            // c_i = sum_j Mdot_ij qd_j - dT/dq_i, with sum_j Mdot_ij qd_j the derivative of
            // p_i along the angles; equal to C qd (checked in the tests).
            let c = (0..n)
                .map(|i| p[i].dt_q(n).sub(&kinetic.diff_q(i)))
                .collect();
            (m, c)
        };
        let gravity: Vec<Expr<C>> = (0..n).map(|i| potential.diff_q(i)).collect();
        Self {
            n,
            kinetic_energy: kinetic,
            potential_energy: potential,
            mass_matrix,
            coriolis,
            gravity,
        }
    }

    /// The Lagrangian L = T - V. Built on demand: for long arms it is as large as T, and
    /// only the paper's route and the printed derivation need it.
    #[must_use]
    pub fn lagrangian(&self) -> Expr<C> {
        self.kinetic_energy.sub(&self.potential_energy)
    }

    /// The torques `tau_i = d/dt dL/dqd_i - dL/dq_i` of Lagrange's equation, per joint, expanded
    /// (assembled as `M qdd + c + g`; equal to [`lagrange_torques`](Self::lagrange_torques)).
    /// Built on demand: they hold as many terms as M, c and g together (see
    /// [`torque_terms`](Self::torque_terms)), which a forty-link arm counts in millions.
    #[must_use]
    pub fn torques(&self) -> Vec<Expr<C>> {
        (0..self.n)
            .map(|i| {
                let mut t = self.coriolis[i].add(&self.gravity[i]);
                for (j, mij) in self.mass_matrix[i].iter().enumerate() {
                    t.add_assign(&mij.mul_var(Var::Qdd(j)));
                }
                t
            })
            .collect()
    }

    /// The terms of [`torques`](Self::torques) without building them, and the coefficients'
    /// parts (`part_count` of each) where `parts`: c's monomials are quadratic in the rates,
    /// g's free of them and each `M_ij qdd_j`'s linear in `qdd_j`, so no two terms merge.
    #[must_use]
    pub fn torque_terms(&self, parts: impl Fn(&C) -> usize) -> usize {
        let count = |e: &Expr<C>| e.terms().map(|(_, _, c)| parts(c)).sum::<usize>();
        (0..self.n)
            .map(|i| {
                count(&self.coriolis[i])
                    + count(&self.gravity[i])
                    + self.mass_matrix[i].iter().map(count).sum::<usize>()
            })
            .sum()
    }

    /// Lagrange's equation, `d/dt dL/dqd_i - dL/dq_i`, expanded: the route of the paper,
    /// independent of how [`derive`](Self::derive) assembles [`torques`](Self::torques) (from
    /// the Hessian of T, Christoffel symbols and dV/dq), and equal to it.
    #[must_use]
    pub fn lagrange_torques(&self) -> Vec<Expr<C>> {
        let lagrangian = self.lagrangian();
        (0..self.n)
            .map(|i| {
                lagrangian
                    .diff_var(rate(i))
                    .dt(self.n)
                    .sub(&lagrangian.diff_q(i))
            })
            .collect()
    }

    /// The Coriolis matrix of Christoffel symbols, row-major, expanded: `C qd = c` and
    /// `Mdot - 2 C` is skew (see [`crate::christoffel`]; the generated method evaluates the
    /// same function by a cheaper route for arms whose joints all turn).
    #[must_use]
    pub fn coriolis_matrix(&self) -> Vec<Vec<Expr<C>>> {
        christoffel::expanded(&self.mass_matrix)
    }

    /// The mass matrix read off Lagrange's equation (the coefficients of the accelerations in
    /// [`lagrange_torques`](Self::lagrange_torques)): an independent reading of M that must
    /// agree with the Hessian of the kinetic energy that [`derive`](Self::derive) takes.
    #[must_use]
    pub fn mass_matrix_from_lagrange(&self) -> Vec<Vec<Expr<C>>> {
        self.lagrange_torques()
            .iter()
            .map(|t| {
                (0..self.n)
                    .map(|j| t.coefficient_of(&Monomial::var(Var::Qdd(j))))
                    .collect()
            })
            .collect()
    }
}

impl<C: Coefficient> fmt::Display for Dynamics<C> {
    /// The derivation in readable notation: L, M, c, g.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "T = {}", self.kinetic_energy)?;
        writeln!(f, "V = {}", self.potential_energy)?;
        writeln!(f, "L = T - V = {}", self.lagrangian())?;
        for i in 0..self.n {
            for j in i..self.n {
                writeln!(f, "M{}{} = {}", i + 1, j + 1, self.mass_matrix[i][j])?;
            }
        }
        for i in 0..self.n {
            writeln!(f, "c{} = {}", i + 1, self.coriolis[i])?;
        }
        for i in 0..self.n {
            writeln!(f, "g{} = {}", i + 1, self.gravity[i])?;
        }
        Ok(())
    }
}

pub mod christoffel;
pub mod definite;
mod metric;
#[cfg(test)]
pub(crate) mod tests;
