//! Planar arms read from model files: a planar arm's own MJCF export reads back to the same
//! `EXACT` and the same bits (an exact round trip), and the control suite's reacher, read as a
//! planar arm, has MuJoCo's dynamics (`tests/models_peers.rs` holds the fixture's check).

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
