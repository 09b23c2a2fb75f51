//! The base parameters of a spatial arm, found exactly.
//!
//! A spatial arm's regressor is too large to multiply out as the planar one is (the PUMA's
//! columns are trigonometric polynomials of thousands of terms), but its geometry is exact, so
//! the unrolled regressor ([`regressor`]) can be evaluated exactly at points of the joints'
//! circles, `cos q = (1 - t^2) / (1 + t^2)` and `sin q = 2 t / (1 + t^2)`. The columns' linear
//! relations are identities in `(q, qd, qdd)` with rational coefficients: they hold at every
//! such point, and at enough random points there are no others. Those points are taken modulo
//! word-sized primes ([`residue`](crate::algebra::residue)) and the relations recovered as
//! fractions ([`modular`](super::modular)), each confirmed by one more prime at fresh points,
//! as computer algebra systems solve large rational systems. Rational elimination on rows of
//! big fractions costs a user's unoptimised build 37 s for the PUMA 560; this, well under a
//! second.
//!
//! This needs exact geometry: rational lengths, gravity and axes, and angles whose cosine and
//! sine are both rational (multiples of pi/2). Mass properties may be anything, run-time
//! parameters included: the regressor does not depend on them.

use num_traits::One;

use super::modular::{dependencies, Sampled};
use crate::algebra::residue::{Prime, Residues};
use crate::algebra::ring::Rational;
use crate::mechanics::spatial::spec::{SpatialArmSpec, SpatialGeometry, SpatialJointSpec};
use crate::methods::identification::regressor::BaseParameters;
use crate::programs::method::Method;
use crate::programs::spatial_regressor::{regressor, standard_parameters, Entry, SpatialParameter};
use crate::slp::Input;

/// A spatial arm's standard parameters and base parameters.
#[derive(Clone, Debug)]
pub struct SpatialIdentification {
    /// The standard parameters, in the regressor's column order.
    pub parameters: Vec<SpatialParameter>,
    /// The base parameters, in the order of the standard parameter each keeps.
    pub base: BaseParameters<Rational>,
}

/// Whether every constant of the arm's regressor is rational (see the module's docs).
#[must_use]
pub fn exact_geometry(arm: &SpatialArmSpec) -> bool {
    let rational = |p: &crate::poly::Poly| p.as_rational().is_some();
    let angle = |a: &crate::mechanics::spatial::FixedAngle| {
        let (c, s) = a.cos_sin();
        rational(&c) && rational(&s)
    };
    let joints = arm.joints.iter().all(|j| match &j.geometry {
        SpatialGeometry::Dh { a, alpha, d, theta }
        | SpatialGeometry::Mdh { a, alpha, d, theta } => {
            rational(a) && rational(d) && angle(alpha) && angle(theta)
        }
        SpatialGeometry::Urdf { xyz, rpy, axis } => {
            xyz.iter().chain(axis).all(rational) && rpy.iter().all(angle)
        }
    });
    joints
        && arm.gravity.iter().chain(&arm.tool_xyz).all(rational)
        && arm.tool_rpy.iter().all(angle)
}

/// The order the elimination takes the columns in: a column is kept when it is not a
/// combination of those before it, so the parameters that Gautier and Khalil's rules keep come
/// first (each link's `xx, xy, xz, yz, zz, mx, my`), then the armatures, then those the rules
/// group into others (`yy, mz, m`), the payload's, and the friction terms.
fn elimination_order(parameters: &[SpatialParameter]) -> Vec<usize> {
    let rank = |e: Entry| -> (u8, usize, usize) {
        const KEPT: [usize; 7] = [4, 5, 7, 8, 9, 1, 2];
        const GROUPED: [usize; 3] = [6, 3, 0];
        match e {
            Entry::Link(i, k) => match KEPT.iter().position(|&x| x == k) {
                Some(at) => (0, i, at),
                None => (2, i, GROUPED.iter().position(|&x| x == k).unwrap_or(0)),
            },
            Entry::Armature(j) => (1, j, 0),
            Entry::Payload(k) => (3, 0, k),
            Entry::Damping(j) => (4, j, 0),
            Entry::Frictionloss(j) => (4, j, 1),
        }
    };
    let mut order: Vec<usize> = (0..parameters.len()).collect();
    order.sort_by_key(|&k| rank(parameters[k].entry));
    order
}

/// The regressor's columns modulo `p` at `count` random points of the joints' circles (a
/// slide's value a random residue), column by column in `order`.
fn sampled(
    arm: &SpatialArmSpec,
    method: &Method,
    order: &[usize],
    count: usize,
    p: Prime,
    residues: &mut Residues,
) -> Option<Sampled> {
    let n = arm.joints.len();
    let mut columns = vec![Vec::with_capacity(n * count); order.len()];
    for _ in 0..count {
        let mut q = Vec::with_capacity(n);
        let mut trig = Vec::with_capacity(n);
        for _ in &arm.joints {
            // (1 - t^2, 2 t) / (1 + t^2): every point of the circle but (-1, 0).
            let t = residues.next(p);
            let t2 = p.mul(t, t);
            let over = p.inv(p.add(1, t2))?;
            trig.push((p.mul(p.sub(1, t2), over), p.mul(p.add(t, t), over)));
            q.push(t);
        }
        let qd: Vec<u64> = (0..n).map(|_| residues.next(p)).collect();
        let qdd: Vec<u64> = (0..n).map(|_| residues.next(p)).collect();
        let input = |i: Input| match i {
            Input::Q(j) => Some(q[j]),
            Input::Qd(j) => Some(qd[j]),
            Input::Qdd(j) => Some(qdd[j]),
            _ => None,
        };
        let mut opaque = || residues.next(p);
        let values = method
            .program
            .eval_mod(p, &input, &|j| trig[j], &mut opaque)?;
        // Outputs are row-major: row i, then every column.
        for (k, (_, id)) in method.outputs.iter().enumerate() {
            columns[k % order.len()].push(values[id.0 as usize]);
        }
    }
    Some(order.iter().map(|&k| (k, columns[k].clone())).collect())
}

/// The standard and base parameters; `None` when the geometry is not exact (see the module's
/// docs), a joint has a spring (whose torque `stiffness (q - springref)` is linear in the
/// angle itself, not a point of its circle: not in this regressor), or a dozen primes have not
/// settled the elimination.
#[must_use]
pub fn identification(arm: &SpatialArmSpec) -> Option<SpatialIdentification> {
    if !exact_geometry(arm) || arm.joints.iter().any(SpatialJointSpec::sprung) {
        return None;
    }
    let parameters = standard_parameters(arm);
    let order = elimination_order(&parameters);
    let all: Vec<usize> = (0..parameters.len()).collect();
    let method = regressor(arm, &parameters, &all);
    // Rows to spare: two points more than the columns need.
    let count = parameters.len().div_ceil(arm.joints.len()) + 2;
    let mut sample = |p: Prime, r: &mut Residues| sampled(arm, &method, &order, count, p, r);
    let (kept, dependent) = dependencies(&mut sample)?;
    let mut grouping: Vec<Vec<(usize, Rational)>> =
        kept.iter().map(|&b| vec![(b, Rational::one())]).collect();
    for (j, combo) in dependent {
        for (b, beta) in combo {
            if let Some(slot) = kept.iter().position(|&c| c == b) {
                grouping[slot].push((j, beta));
            }
        }
    }
    Some(SpatialIdentification {
        parameters,
        base: sorted(BaseParameters {
            columns: kept,
            grouping,
        }),
    })
}
/// The base parameters in the order of the standard parameter each keeps.
fn sorted(base: BaseParameters<Rational>) -> BaseParameters<Rational> {
    let mut pairs: Vec<(usize, Vec<(usize, Rational)>)> =
        base.columns.into_iter().zip(base.grouping).collect();
    pairs.sort_by_key(|(k, _)| *k);
    let (columns, grouping) = pairs.into_iter().unzip();
    BaseParameters { columns, grouping }
}
