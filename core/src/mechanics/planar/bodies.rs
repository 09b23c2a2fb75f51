//! The rigid bodies an arm carries, in the standard parameters its energies are linear in.

use super::spec::ArmSpec;
use crate::ring::{Coefficient, Rational};

/// Each body: (link, centre of mass in the link's frame, mass, inertia about the centre); the
/// payload is a body of the last link.
pub(super) fn bodies<C: Coefficient>(arm: &ArmSpec<C>) -> Vec<(usize, (C, C), &C, &C)> {
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
