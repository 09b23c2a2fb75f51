//! The regressors times the standard parameters against the inverse dynamics.

use super::*;

/// `Y theta` summed by hand from the blocks and the joints' own columns, and both regressors'
/// blocks against each other, for one random arm of mixed joints at a random state.
fn regressor_check<const N: usize>(rng: &mut Rng, worst: &mut Worst) {
    let model: Model<N> = rng.mixed_model();
    let q = rng.configuration(&model, std::f64::consts::PI);
    let qd = rng.vector::<N>(3.0);
    let qdd = rng.vector::<N>(5.0);
    let tau = inverse_dynamics(&model, &q, &qd, &qdd);
    let world = regressor(&model, &q, &qd, &qdd);
    let local = regressor_local(&model, &q, &qd, &qdd);
    for (y, what) in [
        (&world, "world Y theta = tau"),
        (&local, "local Y theta = tau"),
    ] {
        let mut sum = y.payload * payload_parameters(&model);
        for (block, link) in y.links.iter().zip(model.links.iter()) {
            sum += block * link_parameters(link);
        }
        for (i, link) in model.links.iter().enumerate() {
            sum[i] +=
                link.armature * qdd[i] + link.damping * qd[i] + link.frictionloss * y.coulomb[i];
        }
        worst.close(&sum, &tau, 1e-12, what);
        worst.close(&y.torques(&model), &tau, 1e-12, "Regressor::torques = tau");
    }
    for (a, b) in world.links.iter().zip(local.links.iter()) {
        worst.close(a, b, 1e-12, "world vs local blocks");
    }
    worst.close(
        &world.payload,
        &local.payload,
        1e-12,
        "world vs local payload",
    );
    // The regressor depends on the lengths, joint kinds and gravity only.
    let other = Model {
        links: model.links.map(|l| Link {
            mass: 1.0,
            inertia: 0.1,
            com: V2::new(0.3, -0.1),
            armature: 0.0,
            ..l
        }),
        payload: Payload::NONE,
        ..model
    };
    assert_eq!(regressor(&other, &q, &qd, &qdd), world);
    assert_eq!(regressor_local(&other, &q, &qd, &qdd), local);
}

#[test]
fn regressors_give_the_inverse_dynamics_of_mixed_chains() {
    let mut rng = Rng(31);
    let mut worst = Worst::default();
    for _ in 0..200 {
        regressor_check::<1>(&mut rng, &mut worst);
        regressor_check::<2>(&mut rng, &mut worst);
        regressor_check::<3>(&mut rng, &mut worst);
        regressor_check::<4>(&mut rng, &mut worst);
        regressor_check::<5>(&mut rng, &mut worst);
        regressor_check::<6>(&mut rng, &mut worst);
        regressor_check::<7>(&mut rng, &mut worst);
        regressor_check::<8>(&mut rng, &mut worst);
    }
    worst.print("regressors_give_the_inverse_dynamics_of_mixed_chains");
}

/// A horizontal slider reads only the force along its axis: its mass column is the slide's
/// acceleration, and a first moment or an inertia that cannot turn contributes nothing, also
/// under gravity, which acts across the axis.
#[test]
fn slider_regressor_is_its_axial_force() {
    let model = Model::new([Link::rod(0.7, 2.0).with_joint(Joint::Prismatic)], 9.81);
    let (q, qd, qdd) = (
        SVector::from([0.4]),
        SVector::from([-1.5]),
        SVector::from([2.5]),
    );
    let expected = SMatrix::<f64, 1, 4>::new(0.0, 0.0, 0.0, 2.5);
    for y in [
        regressor(&model, &q, &qd, &qdd),
        regressor_local(&model, &q, &qd, &qdd),
    ] {
        assert_eq!(y.links[0], expected);
        assert_eq!(y.payload, expected);
        assert_eq!(y.column("m1"), Some(SVector::from([2.5])));
    }
}
