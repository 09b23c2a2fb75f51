//! Planar arms read from model files: a planar arm's own MJCF export reads back to the same
//! `EXACT` and the same bits (an exact round trip); the control suite's acrobot and cart-pole
//! read as the same `EXACT` as the arms written by hand with the planar keys; and the control
//! suite's models, read as planar arms, have MuJoCo's dynamics (`tests/models_peers.rs` holds
//! the fixture's check).

#[path = "common/export_arms.rs"]
mod export_arms;

use export_arms::PlanarExact;
use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;

/// `PlanarExact::to_mjcf()`, checked in by `tests/export.rs`.
#[derive(PlanarArm)]
#[arm(mjcf = "tests/data/export/planar_exact.xml", tip = "tool")]
struct PlanarBack;

#[test]
fn a_planar_export_reads_back_exactly() {
    assert_eq!(
        PlanarBack::EXACT.to_string(),
        PlanarExact::EXACT.to_string()
    );
    assert_eq!(PlanarBack::JOINT_NAMES, PlanarExact::JOINT_NAMES);
    let (a, b) = (PlanarExact::default(), PlanarBack);
    assert_eq!(a.model(), b.model());
    let mut x = 0.41_f64;
    let mut next = move || {
        x = (x * 9301.0 + 49297.0) % 233_280.0;
        x / 233_280.0 - 0.5
    };
    for _ in 0..5 {
        let q = SVector::<f64, 3>::from_fn(|_, _| next());
        let qd = SVector::<f64, 3>::from_fn(|_, _| next());
        let qdd = SVector::<f64, 3>::from_fn(|_, _| next());
        assert_eq!(a.tip_pose(&q), b.tip_pose(&q));
        assert_eq!(a.mass_matrix(&q), b.mass_matrix(&q));
        assert_eq!(a.bias(&q, &qd), b.bias(&q, &qd));
        assert_eq!(
            a.inverse_dynamics(&q, &qd, &qdd),
            b.inverse_dynamics(&q, &qd, &qdd)
        );
    }
}

/// The control suite's acrobot and cart-pole read as planar arms, and the same arms written by
/// hand with the planar keys: the geometry from the files (the acrobot upright along its
/// plane's x, so gravity along -x; the cart-pole's plane has y = -z, so gravity up y and the
/// pole standing along -y, a quarter turn clockwise from the slide), damping and range as the
/// files say, and each body's moment of inertia about the hinge axis by MuJoCo's compiler's
/// rule for a capsule of radius r, length h and mass m (its mass split between the cylinder and
/// the two hemispheres by volume, `s = 4r/3 / (4r/3 + h)` of it in the hemispheres):
/// `m ((1 - s)(3 r^2 + h^2)/12 + 2 s r^2/5 + s h (3r + 2h)/8)`, written out below. MuJoCo's own
/// `m.body_inertia` (mujoco 4.0.1, in `f64`) agrees to 2 ulp.
#[derive(PlanarArm)]
#[arm(mjcf = "models/acrobot.xml")]
struct AcrobotFile;

#[derive(PlanarArm, Default)]
#[arm(gravity = (-9.81, 0))]
struct AcrobotByHand {
    // r = 0.05, h = 1, m = 1: 4r/3 = 0.2/3.
    #[arm(length = 1, mass = 1, com = 0.5, damping = 0.05,
          inertia = (1 - 0.2/3 / (0.2/3 + 1)) * (3 * 0.05 * 0.05 + 1) / 12
              + 2 * (0.2/3 / (0.2/3 + 1)) * 0.05 * 0.05 / 5
              + (0.2/3 / (0.2/3 + 1)) * (3 * 0.05 + 2) / 8)]
    shoulder: Revolute,
    // r = 0.049: 4r/3 = 0.196/3.
    #[arm(length = 0, mass = 1, com = 0.5, damping = 0.05,
          inertia = (1 - 0.196/3 / (0.196/3 + 1)) * (3 * 0.049 * 0.049 + 1) / 12
              + 2 * (0.196/3 / (0.196/3 + 1)) * 0.049 * 0.049 / 5
              + (0.196/3 / (0.196/3 + 1)) * (3 * 0.049 + 2) / 8)]
    elbow: Revolute,
}

#[derive(PlanarArm)]
#[arm(mjcf = "models/cartpole.xml")]
struct CartPoleFile;

#[derive(PlanarArm, Default)]
#[arm(gravity = (0, 9.81))]
struct CartPoleByHand {
    // A box of half-sizes 0.2, 0.15, 0.1 about y: m (a^2 + c^2) / 3 (a slide never turns it).
    #[arm(length = 0, mass = 1, inertia = (0.2 * 0.2 + 0.1 * 0.1) / 3, damping = 5e-4,
          range = (-1.8, 1.8))]
    slider: Prismatic,
    // r = 0.045, m = 0.1: 4r/3 = 0.06.
    #[arm(length = 0, mass = 0.1, com = 0.5, offset = -pi/2, damping = 2e-6,
          inertia = 0.1 * ((1 - 0.06 / 1.06) * (3 * 0.045 * 0.045 + 1) / 12
              + 2 * (0.06 / 1.06) * 0.045 * 0.045 / 5
              + (0.06 / 1.06) * (3 * 0.045 + 2) / 8))]
    hinge_1: Revolute,
}

#[test]
fn control_suite_models_read_as_the_planar_arms_written_by_hand() {
    assert_eq!(AcrobotFile::JOINT_NAMES, AcrobotByHand::JOINT_NAMES);
    assert_eq!(
        AcrobotFile::EXACT.to_string(),
        AcrobotByHand::EXACT.to_string()
    );
    assert_eq!(CartPoleFile::JOINT_NAMES, CartPoleByHand::JOINT_NAMES);
    assert_eq!(
        CartPoleFile::EXACT.to_string(),
        CartPoleByHand::EXACT.to_string()
    );
    assert_eq!(AcrobotFile.model(), AcrobotByHand::default().model());
    // The file's pole keeps its frame (its centre at (0, -0.5)), the hand's turns by the
    // offset (its centre at 0.5 along it): one arm, as the equal EXACT says.
    let (file, hand) = (CartPoleFile.model(), CartPoleByHand::default().model());
    assert_eq!(
        file.links[1].com,
        planar_arm::nalgebra::Vector2::new(0.0, -0.5)
    );
    assert_eq!(file.links[1].inertia, hand.links[1].inertia);
    assert_eq!(file.gravity, hand.gravity);
    // MuJoCo's compiler, in f64 (`m.body_inertia[b][0]`, about the capsules' transverse axes).
    let mujoco = [
        (
            AcrobotByHand::default().model().links[0].inertia,
            0.0955703125,
        ),
        (
            AcrobotByHand::default().model().links[1].inertia,
            0.09530365719649561,
        ),
        (hand.links[1].inertia, 0.009424592767295598),
        (hand.links[0].inertia, 0.01666666666666667),
    ];
    for (ours, theirs) in mujoco {
        assert!(
            (ours - theirs).abs() <= 4.0 * f64::EPSILON * theirs,
            "{ours} {theirs}"
        );
    }
}
