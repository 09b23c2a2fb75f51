//! The kinetic and potential energies of the bodies an arm carries.

use super::bodies::Body;
use super::kinematics::{link_angle, point_on_link};
use super::metric;
use super::rates::{rate, RateProducts};
use super::spec::{ArmSpec, JointKind};
use crate::expr::{Expr, Var};
use crate::ring::{int, ratio, Coefficient};

/// The potential energy of the bodies, `-m g . p` each with `p` the centre of mass:
/// `m x_joint + m cx cos theta - m cy sin theta` across, `m y_joint + m cx sin theta +
/// m cy cos theta` up (zero at the origin).
pub(super) fn potential_energy<C: Coefficient>(arm: &ArmSpec<C>, bodies: &[Body<C>]) -> Expr<C> {
    let mut potential = Expr::zero();
    let zero = C::from_rational(int(0));
    let (gx, gy) = &arm.gravity;
    for body in bodies {
        let i = body.link;
        let (x_joint, y_joint) = point_on_link(arm, i, &(zero.clone(), zero.clone()));
        let (mx, my) = &arm.turned(i, &body.first_moment);
        let angle = link_angle(arm, i);
        if !gy.is_zero() {
            let y = y_joint
                .scale_by(&body.mass)
                .add(&Expr::sin(mx.clone(), angle.clone()))
                .add(&Expr::cos(my.clone(), angle.clone()));
            potential.sub_assign(&y.scale_by(gy));
        }
        if !gx.is_zero() {
            let x = x_joint
                .scale_by(&body.mass)
                .add(&Expr::cos(mx.clone(), angle.clone()))
                .sub(&Expr::sin(my.clone(), angle));
            potential.sub_assign(&x.scale_by(gx));
        }
    }
    potential
}

/// The joints' springs' energy, `sum stiffness (q_i - springref)^2 / 2`: not the bodies', so
/// not in the energies the regressor's columns are built from.
pub(super) fn spring_energy<C: Coefficient>(arm: &ArmSpec<C>) -> Expr<C> {
    let mut energy = Expr::zero();
    for (i, link) in arm.links.iter().enumerate() {
        if link.stiffness.is_zero() {
            continue;
        }
        let stretch = Expr::var(Var::Q(i)).sub(&Expr::constant(link.springref.clone()));
        energy.add_assign(
            &stretch
                .mul(&stretch)
                .scale_by(&link.stiffness)
                .scale(&ratio(1, 2)),
        );
    }
    energy
}

/// The kinetic energy, built in its pairwise form: a sum over pairs of links `a >= b` of
/// `omega_a omega_b` times `A cos(theta_a - theta_b) - B sin(theta_a - theta_b)`, `A` and `B`
/// summed over the bodies ([`metric`]). Squaring the velocity's x and y expressions
/// gives the same canonical expression (checked in the tests) but creates every
/// `cos(theta_a + theta_b)` term only to cancel it, and dominated the derive's time.
pub(super) fn kinetic_energy<C: Coefficient>(
    arm: &ArmSpec<C>,
    bodies: &[Body<C>],
    rates: &mut RateProducts<C>,
) -> Expr<C> {
    if !arm.all_revolute() {
        return kinetic_energy_of_velocities(arm, bodies);
    }
    let n = arm.links.len();
    rates.sync(arm);
    let senses: Vec<i32> = (0..n).map(|i| arm.sense(i)).collect();
    let metric::Pairs { diag, cross, .. } = metric::pairs(arm, bodies);
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
            let angle = metric::relative_angle(&senses, b, a);
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
pub(super) fn kinetic_energy_of_velocities<C: Coefficient>(
    arm: &ArmSpec<C>,
    bodies: &[Body<C>],
) -> Expr<C> {
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
                let w = Expr::var(rate(j));
                if link.reversed {
                    omega.sub_assign(&w);
                } else {
                    omega.add_assign(&w);
                }
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
        // The first moment turned by the link's offsets, at the angle its joints' `q` give.
        let (hx, hy) = &arm.turned(i, &body.first_moment);
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
