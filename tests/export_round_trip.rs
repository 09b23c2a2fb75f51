//! Export, then import: the files `tests/export.rs` checks in, read back by the derive, are
//! the arms that wrote them: the same mass matrix, bias, gravity and inverse dynamics (to
//! rounding, as the frames differ: a file's body frame is after the joint's motion) and the
//! same tool pose and joint names. MJCF keeps armature and gravity; URDF keeps neither, so
//! the URDF round trips compare arms that have none.

#[path = "common/export_arms.rs"]
mod export_arms;

use export_arms::{DhArm, MdhArm, OriginArm, PlanarMix, PlanarTurned};
use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(mjcf = "tests/data/export/dh_arm.xml", tip = "tool")]
struct DhBack;

#[derive(SpatialArm)]
#[arm(mjcf = "tests/data/export/mdh_arm.xml", tip = "tool")]
struct MdhBack;

#[derive(SpatialArm)]
#[arm(mjcf = "tests/data/export/origin_arm.xml", tip = "tool")]
struct OriginBack;

#[derive(SpatialArm)]
#[arm(urdf = "tests/data/export/mdh_arm.urdf", tip = "tool")]
struct MdhUrdfBack;

#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf", tip = "tool0")]
struct Ur5;

#[derive(SpatialArm)]
#[arm(mjcf = "tests/data/export/planar_mix.xml", tip = "tool")]
struct PlanarMjcfBack;

/// URDF holds no gravity: the plane's is given on the struct.
#[derive(SpatialArm)]
#[arm(urdf = "tests/data/export/planar_mix.urdf", tip = "tool", gravity = (0, -9.81, 0))]
struct PlanarUrdfBack;

/// A planar arm with an offset slide, a reversed hinge, springs and tilted gravity, back as a
/// planar arm and as a spatial one.
#[derive(PlanarArm)]
#[arm(mjcf = "tests/data/export/planar_turned.xml", tip = "tool")]
struct PlanarTurnedBack;

#[derive(SpatialArm)]
#[arm(mjcf = "tests/data/export/planar_turned.xml", tip = "tool")]
struct PlanarTurnedSpatialBack;

#[derive(SpatialArm)]
#[arm(mjcf = "tests/data/export/ur5.xml", tip = "tool")]
struct Ur5MjcfBack;

#[derive(SpatialArm)]
#[arm(urdf = "tests/data/export/ur5.urdf", tip = "tool")]
struct Ur5UrdfBack;

/// Relative to the larger entry, or to 0.01 (N, N m, kg m²) where every entry is smaller: a
/// URDF's angles are radians, so a right angle's zero cosine comes back as 6e-17 and a zero
/// torque as 1e-15.
fn close(a: &[f64], b: &[f64], what: &str) {
    let scale = b.iter().fold(1e-2_f64, |m, x| m.max(x.abs()));
    let d = a
        .iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
        / scale;
    assert!(d < 1e-12, "{what}: {d:e}\n{a:?}\n{b:?}");
}

/// A few states, the same for every arm.
fn states<const N: usize>() -> Vec<[SVector<f64, N>; 3]> {
    let mut x = 0.37_f64;
    let mut next = move || {
        x = (x * 9301.0 + 49297.0) % 233_280.0;
        x / 233_280.0 - 0.5
    };
    (0..4)
        .map(|_| {
            let q = SVector::<f64, N>::from_fn(|_, _| next());
            let qd = SVector::<f64, N>::from_fn(|_, _| 2.0 * next());
            let qdd = SVector::<f64, N>::from_fn(|_, _| 2.0 * next());
            [q, qd, qdd]
        })
        .collect()
}

/// The same dynamics: M, bias, gravity, inverse dynamics.
fn same_dynamics<const N: usize, A: Dynamics<N>, B: Dynamics<N>>(a: &A, b: &B, what: &str) {
    for [q, qd, qdd] in states::<N>() {
        close(
            a.mass_matrix(&q).as_slice(),
            b.mass_matrix(&q).as_slice(),
            what,
        );
        close(a.bias(&q, &qd).as_slice(), b.bias(&q, &qd).as_slice(), what);
        close(a.gravity(&q).as_slice(), b.gravity(&q).as_slice(), what);
        close(
            a.inverse_dynamics(&q, &qd, &qdd).as_slice(),
            b.inverse_dynamics(&q, &qd, &qdd).as_slice(),
            what,
        );
    }
}

fn same<const N: usize, A: SpatialArm<N>, B: SpatialArm<N>>(a: &A, b: &B, what: &str) {
    assert_eq!(A::JOINT_NAMES, B::JOINT_NAMES, "{what}");
    same_dynamics(a, b, what);
    for [q, ..] in states::<N>() {
        let (pa, pb) = (
            a.tip_pose(&q).to_homogeneous(),
            b.tip_pose(&q).to_homogeneous(),
        );
        close(pa.as_slice(), pb.as_slice(), what);
    }
}

#[test]
fn mjcf_exports_read_back_to_the_same_arms() {
    same(&DhArm::default(), &DhBack, "dh");
    same(&MdhArm::default(), &MdhBack, "mdh");
    same(&OriginArm::default(), &OriginBack, "origin");
    same(&Ur5, &Ur5MjcfBack, "ur5 via mjcf");
}

#[test]
fn urdf_exports_read_back_to_the_same_arms() {
    same(&MdhArm::default(), &MdhUrdfBack, "mdh via urdf");
    same(&Ur5, &Ur5UrdfBack, "ur5 via urdf");
}

/// A planar arm written as a spatial one in the x-y plane: the same dynamics and tip.
fn same_planar<const N: usize, A: PlanarArm<N>, B: SpatialArm<N>>(a: &A, b: &B, what: &str) {
    assert_eq!(A::JOINT_NAMES, B::JOINT_NAMES, "{what}");
    same_dynamics(a, b, what);
    for [q, ..] in states::<N>() {
        let (pa, pb) = (a.tip_pose(&q), b.tip_pose(&q));
        let turn = pb.rotation * planar_arm::nalgebra::Vector3::x();
        let theirs = [
            pb.translation.x,
            pb.translation.y,
            pb.translation.z,
            turn.y.atan2(turn.x),
        ];
        let ours = [pa.translation.x, pa.translation.y, 0.0, pa.rotation.angle()];
        close(&ours, &theirs, what);
    }
}

#[test]
fn planar_exports_read_back_as_spatial_arms_of_the_same_dynamics() {
    same_planar(&PlanarMix::default(), &PlanarMjcfBack, "planar via mjcf");
    // URDF cannot hold armature: compare the arm without it.
    let mut bare = PlanarMix::default().model();
    bare.links[1].armature = 0.0;
    let back = PlanarUrdfBack;
    for [q, qd, qdd] in states::<3>() {
        let ours = planar_arm::reference::inverse_dynamics(&bare, &q, &qd, &qdd);
        close(
            ours.as_slice(),
            back.inverse_dynamics(&q, &qd, &qdd).as_slice(),
            "planar via urdf",
        );
    }
}

#[test]
fn turned_planar_exports_read_back_as_planar_and_spatial_arms() {
    let arm = PlanarTurned::default();
    same_planar(
        &arm,
        &PlanarTurnedSpatialBack,
        "turned planar via mjcf, spatial",
    );
    assert_eq!(PlanarTurned::JOINT_NAMES, PlanarTurnedBack::JOINT_NAMES);
    same_dynamics(&arm, &PlanarTurnedBack, "turned planar via mjcf, planar");
    for [q, ..] in states::<3>() {
        let (a, b) = (arm.tip_pose(&q), PlanarTurnedBack.tip_pose(&q));
        close(
            a.translation.vector.as_slice(),
            b.translation.vector.as_slice(),
            "turned planar tip",
        );
    }
}

#[test]
fn right_angle_twists_read_back_exactly() {
    // The MDH arm's twists are right angles, written as whole degrees: the arm read back
    // has exact twists and so exact base parameters, as the original.
    assert_eq!(MdhArm::base_parameter_names().len(), 8);
    assert_eq!(MdhBack::base_parameter_names().len(), 8);
    assert!(MdhBack::EXACT.expansion.is_some());
}
