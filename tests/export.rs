//! `to_mjcf` and `to_urdf`: the files checked in under `tests/data/export/` are what the
//! arms write now (rewrite them with `PLANAR_ARM_BLESS=1 cargo test --test export`, then read
//! the diff); `tests/export_round_trip.rs` derives the arms back from them, and
//! `bench/models/load_exports.py` loads them in MuJoCo and Pinocchio by hand.

#[path = "common/export_arms.rs"]
mod export_arms;
#[path = "../examples/support/puma_arm.rs"]
mod puma_arm;

use export_arms::{DhArm, MdhArm, OriginArm, PlanarExact, PlanarMix, PlanarTurned};
use planar_arm::prelude::*;
use puma_arm::Puma560;

/// The UR5 of example-robot-data, exported again.
#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf", tip = "tool0")]
struct Ur5;

fn same_as_checked_in(name: &str, text: &str) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/export")
        .join(name);
    if std::env::var_os("PLANAR_ARM_BLESS").is_some() {
        std::fs::write(&path, text).unwrap();
    }
    let expected = std::fs::read_to_string(&path)
        .unwrap_or_else(|_| panic!("{name} exists; write it with PLANAR_ARM_BLESS=1"));
    assert_eq!(
        text, expected,
        "{name} changed; rewrite with PLANAR_ARM_BLESS=1 and read the diff"
    );
}

#[test]
fn exports_are_the_checked_in_files() {
    same_as_checked_in("dh_arm.xml", &DhArm::default().to_mjcf());
    same_as_checked_in("mdh_arm.xml", &MdhArm::default().to_mjcf());
    same_as_checked_in("origin_arm.xml", &OriginArm::default().to_mjcf());
    same_as_checked_in("ur5.xml", &Ur5.to_mjcf());
    same_as_checked_in("dh_arm.urdf", &DhArm::default().to_urdf());
    same_as_checked_in("mdh_arm.urdf", &MdhArm::default().to_urdf());
    same_as_checked_in("ur5.urdf", &Ur5.to_urdf());
    same_as_checked_in("planar_mix.xml", &PlanarMix::default().to_mjcf());
    same_as_checked_in("planar_mix.urdf", &PlanarMix::default().to_urdf());
    same_as_checked_in("planar_exact.xml", &PlanarExact::default().to_mjcf());
    same_as_checked_in("planar_turned.xml", &PlanarTurned::default().to_mjcf());
}

#[test]
fn right_angles_are_whole_degrees_and_bad_inertias_are_named() {
    let text = DhArm::default().to_mjcf();
    // Rx(pi/2) Rz(-pi/6), written Rz Ry Rx: exactly 30 and 90 degrees.
    assert!(
        text.contains("<body name=\"upper_link\" pos=\"0 0 0.3\" euler=\"0 30 90\">"),
        "{text}"
    );
    // The PUMA's waist has only Iyy: MuJoCo would refuse it without balanceinertia.
    let puma = Puma560::default().to_mjcf();
    assert!(puma.contains("balanceinertia=\"true\""), "{puma}");
    assert!(puma.contains("as these links' do: waist, elbow;"), "{puma}");
    // URDF has no armature: the file says it left it out.
    let urdf = DhArm::default().to_urdf();
    assert!(urdf.contains("the armature of fore"), "{urdf}");
}
