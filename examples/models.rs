//! Arms from the model files users already have: the DeepMind control suite's acrobot and
//! cart-pole (MJCF) as planar arms and the UR5 (URDF) as a spatial one, derived at compile time
//! from `models/`; each one's joints, mass matrix at a state and gravity torques, then the UR5
//! written back as MJCF.
//!
//! `q` is MuJoCo's `qpos` (the URDF's joint values): the numbers below are MuJoCo's and
//! Pinocchio's for the same files (`tests/models_peers.rs` checks them to 1e-15).
//!
//! ```text
//! cargo run --example models
//! ```

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;

/// `dm_control/suite/acrobot.xml`: two capsules on a hinge, a second hinge between them, both
/// about the y axis. Upright at `qpos = 0`: its links stand along its plane's x, so gravity
/// points along -x of the plane.
#[derive(PlanarArm)]
#[arm(mjcf = "models/acrobot.xml")]
struct Acrobot;

/// `dm_control/suite/cartpole.xml`: a cart on a slide and a pole on a hinge.
#[derive(PlanarArm)]
#[arm(mjcf = "models/cartpole.xml")]
struct CartPole;

/// The UR5 of example-robot-data, to its tool flange.
#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf", tip = "tool0")]
struct Ur5;

/// The joints, `q`, `M(q)` and `g(q)` of a planar or spatial arm (one dynamics trait).
fn dynamics<const N: usize, A: Dynamics<N>>(names: &[&str], arm: &A, q: &SVector<f64, N>) {
    println!("  joints  {}", names.join(", "));
    println!("  q       {:.3?}", q.as_slice());
    let m = arm.mass_matrix(q);
    for (i, row) in m.row_iter().enumerate() {
        let label = if i == 0 { "  M(q)   " } else { "         " };
        let row: Vec<String> = row.iter().map(|x| format!("{x:9.5}")).collect();
        println!("{label}[{}]", row.join(" "));
    }
    let g: Vec<String> = arm.gravity(q).iter().map(|x| format!("{x:.5}")).collect();
    println!("  g(q)    [{}]", g.join(", "));
}

fn planar<const N: usize, A: PlanarArm<N>>(title: &str, arm: &A, q: &SVector<f64, N>) {
    println!("{title}");
    dynamics(&A::JOINT_NAMES, arm, q);
    let g = arm.model().gravity;
    println!("  gravity ({:.4}, {:.4}) in the plane", g.x, g.y);
    let p = arm.tip_pose(q).translation.vector;
    println!("  tip     ({:.4}, {:.4}) in the plane\n", p.x, p.y);
}

fn spatial<const N: usize, A: SpatialArm<N>>(title: &str, arm: &A, q: &SVector<f64, N>) {
    println!("{title}");
    dynamics(&A::JOINT_NAMES, arm, q);
    let p = arm.tip_pose(q).translation.vector;
    println!("  tip     ({:.4}, {:.4}, {:.4})\n", p.x, p.y, p.z);
}

fn main() {
    planar(
        "acrobot (models/acrobot.xml)",
        &Acrobot,
        &SVector::from([0.3, -0.5]),
    );
    planar(
        "cart-pole (models/cartpole.xml)",
        &CartPole,
        &SVector::from([0.1, 0.4]),
    );
    spatial(
        "UR5 (models/ur5.urdf)",
        &Ur5,
        &SVector::from([0.0, -1.2, 1.0, -0.5, 0.3, 0.0]),
    );
    println!("The UR5 written back as MJCF (MuJoCo loads it; #[arm(mjcf = ..)] reads it):\n");
    print!("{}", Ur5.to_mjcf());
}
