//! An arm is an ordinary struct: doc comments, other derives, visibility, attributes, const
//! generics, and use through a generic function all work.
#![deny(warnings)]

use std::collections::HashSet;

use planar_arm::prelude::*;

/// A documented arm.
#[derive(PlanarArm, Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
#[arm(gravity = 9.81)]
#[allow(clippy::struct_field_names)]
pub struct Documented {
    /// The upper arm.
    #[arm(length = 0.4, mass = 2)]
    pub upper: Revolute,
    /// The forearm, with its own inertia.
    #[arm(length = 0.3, mass = 1)]
    #[arm(inertia = 0.01, com = 0.12)]
    pub(crate) fore: Revolute,
}

/// A const parameter is carried through to the impl.
#[derive(PlanarArm, Default)]
struct Tagged<const TAG: usize> {
    #[arm(length = 1, mass = 1)]
    only: Revolute,
}

fn tip_height<A: PlanarArm<N>, const N: usize>(arm: &A, q: &SVector<f64, N>) -> f64 {
    arm.tip_pose(q).translation.vector.y
}

fn main() {
    let arm = Documented::default();
    let copy = arm;
    assert_eq!(arm, copy.clone());
    assert_eq!(
        format!("{arm:?}"),
        "Documented { upper: Revolute, fore: Revolute }"
    );
    let set: HashSet<Documented> = [arm, copy].into_iter().collect();
    assert_eq!(set.len(), 1);
    let q = SVector::<f64, 2>::new(core::f64::consts::FRAC_PI_2, 0.0);
    assert!((tip_height(&arm, &q) - 0.7).abs() < 1e-12);
    assert_eq!(arm.links()[1].inertia, 0.01);
    let [up, _] = arm.inverse_kinematics(&Point2::new(0.5, 0.2)).unwrap();
    let reached = arm.tip_pose(&up).translation.vector;
    assert!((reached.x - 0.5).abs() < 1e-12 && (reached.y - 0.2).abs() < 1e-12);

    let tagged = Tagged::<7>::default();
    let q = SVector::<f64, 1>::new(0.0);
    assert!((tagged.gravity(&q)[0] - 9.80665 * 0.5).abs() < 1e-12);
    assert!(
        (tip_height(
            &tagged,
            &SVector::<f64, 1>::new(core::f64::consts::FRAC_PI_2)
        ) - 1.0)
            .abs()
            < 1e-12
    );
}
