//! Arms read from model files (`models/`, copied with their licences) against the same arms
//! written by hand with attributes: the same `EXACT` and the same numbers, bit for bit.

#![allow(clippy::approx_constant)] // the file's 3.14159265359 is its value, not pi

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;

/// The UR5 of example-robot-data, to its tool flange `tool0`.
#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf", tip = "tool0")]
struct Ur5File;

/// The same UR5 typed from the file: `world` and `base_link` do not move and are dropped;
/// `tool0` hangs from `wrist_3_link` by a fixed joint, so it is the tool frame.
#[derive(SpatialArm, Default)]
#[arm(tool(xyz = (0, 0.0823, 0), rpy = (-1.57079632679, 0, 0)))]
struct Ur5Hand {
    #[arm(origin(xyz = (0, 0, 0.089159)), axis = (0, 0, 1), range = (-6.28318530718, 6.28318530718),
          mass = 3.7, inertia(xx = 0.010267495893, yy = 0.010267495893, zz = 0.00666))]
    shoulder_pan_joint: Revolute,
    #[arm(origin(xyz = (0, 0.13585, 0), rpy = (0, 1.57079632679, 0)), axis = (0, 1, 0),
          range = (-6.28318530718, 6.28318530718),
          mass = 8.393, com = (0, 0, 0.28), inertia(xx = 0.22689067591, yy = 0.22689067591, zz = 0.0151074))]
    shoulder_lift_joint: Revolute,
    #[arm(origin(xyz = (0, -0.1197, 0.425)), axis = (0, 1, 0), range = (-3.14159265359, 3.14159265359),
          mass = 2.275, com = (0, 0, 0.25), inertia(xx = 0.049443313556, yy = 0.049443313556, zz = 0.004095))]
    elbow_joint: Revolute,
    #[arm(origin(xyz = (0, 0, 0.39225), rpy = (0, 1.57079632679, 0)), axis = (0, 1, 0),
          range = (-6.28318530718, 6.28318530718),
          mass = 1.219, inertia(xx = 0.111172755531, yy = 0.111172755531, zz = 0.21942))]
    wrist_1_joint: Revolute,
    #[arm(origin(xyz = (0, 0.093, 0)), axis = (0, 0, 1), range = (-6.28318530718, 6.28318530718),
          mass = 1.219, inertia(xx = 0.111172755531, yy = 0.111172755531, zz = 0.21942))]
    wrist_2_joint: Revolute,
    // wrist_3_link with the massless ee_link and tool0 welded to it.
    #[arm(origin(xyz = (0, 0, 0.09465)), axis = (0, 1, 0), range = (-6.28318530718, 6.28318530718),
          mass = 0.1879, inertia(xx = 0.0171364731454, yy = 0.0171364731454, zz = 0.033822))]
    wrist_3_joint: Revolute,
}

fn states<const N: usize>() -> Vec<[SVector<f64, N>; 3]> {
    // A fixed, dependency-free sequence: the states do not matter, only that both arms see the
    // same ones.
    let mut x = 0.123_f64;
    let mut next = move || {
        x = (x * 9301.0 + 49297.0) % 233_280.0;
        x / 233_280.0 * 2.0 - 1.0
    };
    (0..5)
        .map(|_| core::array::from_fn(|_| SVector::from_fn(|_, _| next())))
        .collect()
}

/// Every method both derives share gives the same bits on both arms.
macro_rules! same_arm {
    ($a:expr, $b:expr, $n:literal) => {{
        let (a, b) = (&$a, &$b);
        for [q, qd, qdd] in states::<$n>() {
            assert_eq!(a.tip_pose(&q), b.tip_pose(&q));
            assert_eq!(a.link_poses(&q), b.link_poses(&q));
            assert_eq!(a.jacobian(&q), b.jacobian(&q));
            assert_eq!(a.mass_matrix(&q), b.mass_matrix(&q));
            assert_eq!(a.bias(&q, &qd), b.bias(&q, &qd));
            assert_eq!(a.gravity(&q), b.gravity(&q));
            assert_eq!(
                a.inverse_dynamics(&q, &qd, &qdd),
                b.inverse_dynamics(&q, &qd, &qdd)
            );
            assert_eq!(
                a.forward_dynamics(&q, &qd, &qdd),
                b.forward_dynamics(&q, &qd, &qdd)
            );
            assert_eq!(a.kinetic_energy(&q, &qd), b.kinetic_energy(&q, &qd));
        }
    }};
}

#[test]
fn ur5_from_its_urdf_is_the_ur5_typed_by_hand() {
    assert_eq!(Ur5File::EXACT.to_string(), Ur5Hand::EXACT.to_string());
    same_arm!(Ur5File, Ur5Hand::default(), 6);
    assert_eq!(
        Ur5File::JOINT_NAMES,
        [
            "shoulder_pan_joint",
            "shoulder_lift_joint",
            "elbow_joint",
            "wrist_1_joint",
            "wrist_2_joint",
            "wrist_3_joint"
        ]
    );
    assert_eq!(Ur5File::JOINT_NAMES, Ur5Hand::JOINT_NAMES);
    // The file's limits are kept.
    let model = Ur5File.model();
    assert_eq!(model.joints[2].range, Some((-3.14159265359, 3.14159265359)));
}

#[path = "common/export_arms.rs"]
mod export_arms;

/// A planar arm as a spatial one in the x-y plane (what `to_mjcf` writes) has the planar
/// arm's dynamics: the spatial reference's Newton-Euler recursion and composite-body mass
/// matrix on `to_spatial` against the planar derive, slides, friction and payload included.
#[test]
fn planar_arms_are_spatial_arms_in_the_plane() {
    use planar_arm::reference::spatial as reference;
    fn check<const N: usize, A: PlanarArm<N>>(arm: &A) {
        let spatial = arm.model().to_spatial();
        for [q, qd, qdd] in states::<N>() {
            let q = q.map(|x| 0.2 + 0.2 * x); // slides inside their range
            let m = reference::mass_matrix(&spatial, &q);
            assert!((m - arm.mass_matrix(&q)).amax() < 1e-12 * m.amax(), "M");
            let tau = reference::inverse_dynamics(&spatial, &q, &qd, &qdd);
            let ours = arm.inverse_dynamics(&q, &qd, &qdd);
            assert!(
                (tau - ours).amax() < 1e-12 * tau.amax().max(1.0),
                "{tau} {ours}"
            );
            let tip = reference::tip_pose(&spatial, &q).translation.vector;
            let planar = arm.tip_pose(&q).translation.vector;
            assert!((tip.xy() - planar).norm() < 1e-12 && tip.z == 0.0);
        }
    }
    check(&export_arms::PlanarExact::default());
    check(&export_arms::PlanarMix::default());
}
