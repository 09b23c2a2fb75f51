//! Run-time parameters in unusual places: a raw identifier, a generic struct, a field that is
//! neither a link nor a parameter, and a struct-level payload read at run time.

use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(gravity = self.r#type, payload = self.load)]
struct Odd<T> {
    #[arm(length = 0.5, mass = self.r#mass, com = (self.r#mass / 4, 0.01))]
    upper: Revolute,
    r#type: f64,
    r#mass: f64,
    load: f64,
    tag: T,
}

fn main() {
    let arm = Odd {
        upper: Revolute,
        r#type: 9.81,
        r#mass: 2.0,
        load: 0.5,
        tag: "label",
    };
    assert_eq!(arm.tag, "label");
    let model = arm.model();
    assert_eq!(model.gravity.y, -9.81);
    assert_eq!(model.links[0].com.x, 0.5);
    assert_eq!(model.payload.mass, 0.5);
    let q = SVector::<f64, 1>::new(0.3);
    let tau = arm.gravity(&q)[0];
    let by_hand = 9.81 * (2.0 * (0.5 * 0.3f64.cos() - 0.01 * 0.3f64.sin()) + 0.5 * 0.5 * 0.3f64.cos());
    assert!((tau - by_hand).abs() < 1e-12, "{tau} vs {by_hand}");
    // The frozen view of a generic struct with raw-named parameters.
    let frozen = arm.freeze();
    let qd = SVector::<f64, 1>::new(-0.4);
    let h = frozen.bias(&q, &qd)[0];
    assert!((h - arm.bias(&q, &qd)[0]).abs() < 1e-12);
}
