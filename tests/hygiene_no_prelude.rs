//! A derived arm compiles and works in a crate without the implicit prelude: the generated
//! code names everything by absolute path.
#![no_implicit_prelude]

use ::planar_arm::nalgebra::SVector;
use ::planar_arm::{Dynamics, PlanarArm};
use ::std::assert;

#[derive(::planar_arm::PlanarArm, ::std::default::Default)]
struct Two {
    #[arm(length = 1, mass = 1)]
    upper: ::planar_arm::Revolute,
    #[arm(length = 0.5, mass = 2)]
    fore: ::planar_arm::Revolute,
}

#[derive(::planar_arm::PlanarArm, ::std::default::Default)]
struct Three {
    #[arm(length = 1, mass = 1)]
    upper: ::planar_arm::Revolute,
    #[arm(length = 0.5, mass = 2)]
    fore: ::planar_arm::Revolute,
    #[arm(length = 0.25, mass = 1)]
    hand: ::planar_arm::Revolute,
}

#[test]
fn works_without_the_prelude() {
    use ::planar_arm::kinematics::{ClosedFormIk, TipForce, TipWrench};

    let two: Two = ::std::default::Default::default();
    let q = SVector::<f64, 2>::new(0.3, 1.1);
    let tau = two.inverse_dynamics(&q, &q, &q);
    let back = two.forward_dynamics(&q, &q, &tau);
    assert!((back - q).amax() < 1e-12);
    let target = two.tip_pose(&q).translation.vector;
    assert!(two
        .inverse_kinematics(&::planar_arm::nalgebra::Point2::new(target.x, target.y))
        .is_ok());
    assert!(two.tip_force(&q, &tau).is_ok());

    let three: Three = ::std::default::Default::default();
    let q = SVector::<f64, 3>::new(0.3, 1.1, -0.4);
    assert!(three.inverse_kinematics(&three.tip_pose(&q)).is_ok());
    assert!(three.tip_wrench(&q, &q).is_ok());
    assert!(three.mass_matrix(&q).cholesky().is_some());
}
