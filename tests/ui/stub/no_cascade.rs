use planar_arm::prelude::*;

// Only the attribute error is reported: the stub impl keeps `mass_matrix` and the rest of the
// trait usable, so this code adds no error of its own.
#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(lenght = 1, mass = 1)]
    fore: Revolute,
}

fn main() {
    let arm = Arm {
        upper: Revolute,
        fore: Revolute,
    };
    let q = SVector::<f64, 2>::new(0.1, 0.2);
    let m: SMatrix<f64, 2, 2> = arm.mass_matrix(&q);
    let qdd = arm.forward_dynamics(&q, &q, &q);
    let _ = arm.inverse_kinematics(&Point2::new(1.0, 0.5));
    let _ = arm.tip_force(&q, &q);
    println!("{m} {qdd} {}", arm.links()[0].length);
}
