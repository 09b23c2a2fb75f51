//! The friction law, and arms without links, without mass or with NaN in their state.

use super::*;

#[test]
fn friction_law() {
    let links = [
        Link::rod(1.0, 1.0).with_damping(0.5).with_frictionloss(0.2),
        Link::rod(1.0, 1.0).with_damping(0.5),
        Link::rod(1.0, 1.0).with_frictionloss(0.2),
    ];
    let model = Model::new(links, 9.81);
    // sign(0) = sign(-0) = 0: no Coulomb friction at rest, whichever zero.
    for zero in [0.0, -0.0] {
        let f = friction(&model, &SVector::from([zero; 3]));
        assert_eq!(f, SVector::<f64, 3>::zeros());
    }
    let f = friction(&model, &SVector::from([-2.0, 3.0, 1e-300]));
    assert_eq!(f, SVector::from([-1.0 - 0.2, 1.5, 0.2]));
    // The viscous part is linear in qd; the Coulomb part depends on its sign alone.
    let viscous = Model::new(links.map(|l| l.with_frictionloss(0.0)), 9.81);
    let mut rng = Rng(6);
    for _ in 0..50 {
        let (a, b) = (rng.vector::<3>(5.0), rng.vector::<3>(5.0));
        let k = rng.uniform(-3.0, 3.0);
        assert_close(
            &friction(&viscous, &(a * k + b)),
            &(friction(&viscous, &a) * k + friction(&viscous, &b)),
            1e-14,
            "damping is linear",
        );
        let coulomb = |v: &SVector<f64, 3>| friction(&model, v) - friction(&viscous, v);
        assert_close(
            &coulomb(&(a * 7.0)),
            &coulomb(&a),
            1e-13,
            "Coulomb depends on the sign alone",
        );
    }
    // NaN in gives NaN out, also through a frictionless joint.
    let f = friction(&model, &SVector::from([f64::NAN; 3]));
    assert!(f.iter().all(|x| x.is_nan()), "{f}");
}

#[test]
fn no_links_no_panic() {
    let model = Model::<0>::new([], 9.81).with_payload(Payload::point(1.0));
    let z = SVector::<f64, 0>::zeros();
    assert_eq!(model.rigid_links(), []);
    assert_eq!(inverse_dynamics(&model, &z, &z, &z).len(), 0);
    assert_eq!(forward_dynamics(&model, &z, &z, &z).len(), 0);
    assert_eq!(forward_dynamics_crba(&model, &z, &z, &z).len(), 0);
    assert_eq!(mass_matrix(&model, &z).len(), 0);
    assert_eq!(gravity_torques(&model, &z).len(), 0);
    assert_eq!(kinetic_energy(&model, &z, &z), 0.0);
    assert_eq!(potential_energy(&model, &z), 0.0);
    assert_eq!(tip_position(&model, &z), Point2::origin());
    assert_eq!(tip_orientation(&model, &z), 0.0);
    assert_eq!(regressor(&model, &z, &z, &z).payload.len(), 0);
    assert_eq!(regressor_local(&model, &z, &z, &z).payload.len(), 0);
}

#[test]
fn degenerate_arm_gives_nan_not_a_panic() {
    for joint in [Joint::Revolute, Joint::Prismatic] {
        let massless = Model::new([Link::rod(1.0, 0.0).with_joint(joint)], 9.81);
        let one = SVector::from([1.0]);
        assert!(forward_dynamics_crba(&massless, &one, &one, &one)[0].is_nan());
        // A rotor (or a reflected mass) alone makes it well posed: qdd = tau / armature.
        let geared = Model::new(
            [Link::rod(1.0, 0.0).with_armature(0.5).with_joint(joint)],
            9.81,
        );
        let rest = SVector::zeros();
        assert_close_f(
            forward_dynamics_crba(&geared, &one, &rest, &one)[0],
            2.0,
            1e-15,
            "CRBA",
        );
        assert_close_f(
            forward_dynamics(&geared, &one, &rest, &one)[0],
            2.0,
            1e-15,
            "ABA",
        );
    }
}

/// Non-finite input gives non-finite output through a prismatic joint too, never a panic.
#[test]
fn nan_through_a_slider_is_nan() {
    let model = Model::new(
        [
            Link::rod(0.5, 1.0),
            Link::rod(0.4, 1.0).with_joint(Joint::Prismatic),
            Link::rod(0.3, 1.0),
        ],
        9.81,
    );
    let nan = SVector::from([0.2, f64::NAN, -0.4]);
    let finite = SVector::from([0.3, 0.1, -0.2]);
    assert!(inverse_dynamics(&model, &nan, &finite, &finite)[0].is_nan());
    assert!(forward_dynamics(&model, &nan, &finite, &finite)[0].is_nan());
    assert!(mass_matrix(&model, &nan)[(0, 0)].is_nan());
    assert!(tip_position(&model, &nan).x.is_nan());
    // The slide does not turn the last link.
    assert_eq!(tip_orientation(&model, &nan), 0.2 - 0.4);
}
