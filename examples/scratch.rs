use planar_arm::prelude::*;

/// The paper's three equal links.
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
pub struct Horn3 {
    #[arm(length = 1, mass = 1)]
    pub upper: Revolute,
    #[arm(length = 1, mass = 1, inertia = 1/12, com = 1/2)]
    pub fore: Revolute,
    #[arm(length = 0.35, mass = 3/2)]
    pub hand: Revolute,
}

fn main() {
    let arm = Horn3::default();
    let q = SVector::<f64, 3>::new(0.3, -0.7, 1.1);
    let qd = SVector::<f64, 3>::new(0.5, 0.2, -1.0);
    let qdd = SVector::<f64, 3>::new(0.1, -0.3, 0.4);
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    let r = planar_arm::reference::inverse_dynamics(&Horn3::LINKS, Horn3::GRAVITY, &q, &qd, &qdd);
    println!("{tau} {r}");
    let back = arm.forward_dynamics(&q, &qd, &tau);
    println!("{back}");
    println!(
        "{}",
        arm.mass_matrix(&q) - planar_arm::reference::mass_matrix(&Horn3::LINKS, &q)
    );
}
