//! Positions of points on the links, and the forward kinematics and statics built from them.

use super::spec::{ArmSpec, JointKind, LinkSpec};
use crate::expr::{Expr, Var};
use crate::ring::{int, Coefficient, Rational};
use crate::trig::Angle;

/// Forward kinematics and statics of the arm, exact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Kinematics<C = Rational> {
    /// Number of joints.
    pub n: usize,
    /// Each link's frame origin `(x, y)` (its joint; for a prismatic joint the slid carriage,
    /// so joint 1 is at the origin unless it is prismatic), then the tip last (n + 1 entries).
    pub points: Vec<(Expr<C>, Expr<C>)>,
    /// The absolute angle of the last link, less its joints' offsets.
    pub tip_angle: Angle,
    /// `(cos, sin)` of the last link's joints' offsets together ([`ArmSpec::turn`]): the tip's
    /// orientation is `tip_angle` turned by it.
    pub tip_turn: (C, C),
    /// The 3 x n Jacobian, row-major: d/dt of tip x, tip y, last angle.
    pub jacobian: Vec<Vec<Expr<C>>>,
    /// `r^2 = x^2 + y^2` of the tip: independent of q1.
    pub radius_squared: Expr<C>,
}

/// Absolute angle of link `i` (0-based) less its joints' offsets: the sum of the revolute
/// joints' angles up to it (minus those of reversed joints), `q_1 + ... + q_{i+1}` when all
/// are revolute (a prismatic joint does not turn its link).
pub(super) fn link_angle<C>(arm: &ArmSpec<C>, i: usize) -> Angle {
    Angle::new(
        arm.links[..=i]
            .iter()
            .map(|l| match (l.joint, l.reversed) {
                (JointKind::Prismatic, _) => 0,
                (JointKind::Revolute, false) => 1,
                (JointKind::Revolute, true) => -1,
            })
            .collect(),
    )
}

/// `R(theta) v` for `theta` the angle `angle` and `v` constant: `(x, y)`.
fn rotated<C: Coefficient>(angle: &Angle, v: &(C, C)) -> (Expr<C>, Expr<C>) {
    let (a, b) = v;
    (
        Expr::cos(a.clone(), angle.clone()).sub(&Expr::sin(b.clone(), angle.clone())),
        Expr::sin(a.clone(), angle.clone()).add(&Expr::cos(b.clone(), angle.clone())),
    )
}

/// `(x, y)` of the point `at` (in link `i`'s frame, from its own frame's origin) of link `i`:
/// the earlier links full length, and each prismatic joint up to `i` sliding its link by `q_k`
/// (`-q_k` reversed) along its frame's x. Each vector of a link's frame enters turned by its
/// offsets ([`ArmSpec::turned`]) at the angle its joints' `q` give.
pub(super) fn point_on_link<C: Coefficient>(
    arm: &ArmSpec<C>,
    i: usize,
    at: &(C, C),
) -> (Expr<C>, Expr<C>) {
    let zero = || C::from_rational(int(0));
    let mut x = Expr::zero();
    let mut y = Expr::zero();
    for (j, link) in arm.links.iter().enumerate().take(i) {
        let (dx, dy) = rotated(
            &link_angle(arm, j),
            &arm.turned(j, &(link.length.clone(), zero())),
        );
        x.add_assign(&dx);
        y.add_assign(&dy);
    }
    for (k, link) in arm.links.iter().enumerate().take(i + 1) {
        if link.joint == JointKind::Prismatic {
            let sense = C::from_rational(int(i64::from(arm.sense(k))));
            let (dx, dy) = rotated(&link_angle(arm, k), &arm.turned(k, &(sense, zero())));
            x.add_assign(&dx.mul_var(Var::Q(k)));
            y.add_assign(&dy.mul_var(Var::Q(k)));
        }
    }
    let (dx, dy) = rotated(&link_angle(arm, i), &arm.turned(i, at));
    (x.add(&dx), y.add(&dy))
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
                .enumerate()
                .map(|(i, l)| match l.joint {
                    JointKind::Revolute => {
                        Expr::constant(C::from_rational(int(i64::from(arm.sense(i)))))
                    }
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
            tip_turn: if n == 0 {
                (C::from_rational(int(1)), zero())
            } else {
                arm.turn(n - 1)
            },
            jacobian,
            radius_squared,
        }
    }
}
