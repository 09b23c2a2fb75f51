use planar_arm::prelude::*;

// Only the attribute error is reported: the stub impl keeps the trait usable, so this code adds
// no error of its own.
#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4, alpha = pi/2))]
    shoulder: Revolute,
    #[arm(dh(a = 0.3, alhpa = 0))]
    elbow: Revolute,
}

fn main() {
    let arm = Arm {
        shoulder: Revolute,
        elbow: Revolute,
    };
    let q = SVector::<f64, 2>::new(0.1, 0.2);
    let pose = arm.tip_pose(&q);
    let j: SMatrix<f64, 6, 2> = arm.jacobian(&q);
    let g = arm.gravity(&q);
    println!("{pose} {j} {g}");
}
