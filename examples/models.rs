//! Arms from the model files users already have: the DeepMind control suite's acrobot and
//! cart-pole (MJCF) and the UR5 (URDF), derived at compile time from `models/`; each one's
//! joints, mass matrix at a state and gravity torques, then the UR5 written back as MJCF.
//!
//! `q` is MuJoCo's `qpos` (the URDF's joint values): the numbers below are MuJoCo's and
//! Pinocchio's for the same files (`tests/models_peers.rs` checks them to 1e-15).
//!
//! ```text
//! cargo run --example models
//! ```

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;

/// `dm_control/suite/acrobot.xml`: two capsules hanging from a hinge, a second hinge between
/// them, both about the y axis.
#[derive(SpatialArm)]
#[arm(mjcf = "models/acrobot.xml")]
struct Acrobot;

/// `dm_control/suite/cartpole.xml`: a cart on a slide and a pole on a hinge.
#[derive(SpatialArm)]
#[arm(mjcf = "models/cartpole.xml")]
struct CartPole;

/// The UR5 of example-robot-data, to its tool flange.
#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf", tip = "tool0")]
struct Ur5;

fn show<const N: usize, A: SpatialArm<N>>(title: &str, arm: &A, q: &SVector<f64, N>) {
    println!("{title}");
    println!("  joints  {}", A::JOINT_NAMES.join(", "));
    println!("  q       {:.3?}", q.as_slice());
    let m = arm.mass_matrix(q);
    for (i, row) in m.row_iter().enumerate() {
        let label = if i == 0 { "  M(q)   " } else { "         " };
        let row: Vec<String> = row.iter().map(|x| format!("{x:9.5}")).collect();
        println!("{label}[{}]", row.join(" "));
    }
    let g: Vec<String> = arm.gravity(q).iter().map(|x| format!("{x:.5}")).collect();
    println!("  g(q)    [{}]", g.join(", "));
    let p = arm.tip_pose(q).translation.vector;
    println!("  tip     ({:.4}, {:.4}, {:.4})\n", p.x, p.y, p.z);
}

fn main() {
    show(
        "acrobot (models/acrobot.xml)",
        &Acrobot,
        &SVector::from([0.3, -0.5]),
    );
    show(
        "cart-pole (models/cartpole.xml)",
        &CartPole,
        &SVector::from([0.1, 0.4]),
    );
    show(
        "UR5 (models/ur5.urdf)",
        &Ur5,
        &SVector::from([0.0, -1.2, 1.0, -0.5, 0.3, 0.0]),
    );
    println!("The UR5 written back as MJCF (MuJoCo loads it; #[arm(mjcf = ..)] reads it):\n");
    print!("{}", Ur5.to_mjcf());
}
