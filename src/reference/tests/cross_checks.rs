//! The algorithms against each other and against the energies' derivatives, for random arms of
//! revolute and of mixed joints; the armature and the payload against the same arm without
//! them.

use super::*;

/// All the cross-checks between algorithms for one arm at a random state.
fn cross_check<const N: usize>(rng: &mut Rng, model: &Model<N>, worst: &mut Worst) {
    let q = rng.configuration(model, std::f64::consts::PI);
    let qd = rng.vector::<N>(3.0);
    let tau = rng.vector::<N>(20.0);
    let zero = SVector::<f64, N>::zeros();
    let tol = 1e-10;

    // CRBA against columns of RNEA(qd = 0, g = 0, qdd = e_j); friction vanishes at rest.
    let m = mass_matrix(model, &q);
    // No gravity and no springs: no static torques.
    let weightless = Model {
        gravity: nalgebra::Vector2::zeros(),
        links: model.links.map(|l| Link {
            stiffness: 0.0,
            ..l
        }),
        ..*model
    };
    let m_rnea = SMatrix::<f64, N, N>::from_fn(|i, j| {
        inverse_dynamics(&weightless, &q, &zero, &basis(j, 1.0))[i]
    });
    worst.close(&m, &m_rnea, tol, "CRBA vs RNEA columns");
    worst.close(&m, &m.transpose(), 0.0, "M symmetric");

    // Bias decomposition; gravity against RNEA at rest with the friction off too.
    let bias = bias_forces(model, &q, &qd);
    let grav = gravity_torques(model, &q);
    let cor = coriolis(model, &q, &qd);
    let fric = friction(model, &qd);
    let frictionless = Model {
        links: model
            .links
            .map(|l| l.with_damping(0.0).with_frictionloss(0.0)),
        ..*model
    };
    worst.close(&bias, &(cor + grav + fric), tol, "bias = c + g + f");
    worst.close(
        &grav,
        &inverse_dynamics(&frictionless, &q, &zero, &zero),
        tol,
        "g vs RNEA at rest",
    );
    worst.close(
        &inverse_dynamics_batched_trig(model, &q, &qd, &tau),
        &inverse_dynamics(model, &q, &qd, &tau),
        tol,
        "batched trigonometry",
    );
    let qdd = rng.vector::<N>(5.0);
    worst.close(
        &inverse_dynamics(model, &q, &qd, &qdd),
        &(m * qdd + bias),
        tol,
        "RNEA = M qdd + bias",
    );

    // ABA against CRBA + Cholesky, and round trip through inverse dynamics.
    let qdd_aba = forward_dynamics(model, &q, &qd, &tau);
    let qdd_crba = forward_dynamics_crba(model, &q, &qd, &tau);
    worst.close(&qdd_aba, &qdd_crba, tol, "ABA vs CRBA");
    worst.close(
        &inverse_dynamics(model, &q, &qd, &qdd_aba),
        &tau,
        tol,
        "RNEA(ABA(tau))",
    );
    worst.close(&(m * qdd_aba + bias), &tau, tol, "M qdd + bias = tau");

    // Kinetic energy against the mass matrix, both ways: T = qd' M qd / 2, and M is the
    // Hessian of T in qd. T is exactly quadratic in qd, so central second differences
    // with a unit step have no truncation error, only rounding.
    let t = |v: &SVector<f64, N>| kinetic_energy(model, &q, v);
    worst.close_f(t(&qd), 0.5 * qd.dot(&(m * qd)), tol, "T = qd' M qd / 2");
    let hessian = SMatrix::<f64, N, N>::from_fn(|i, j| {
        let (ei, ej) = (basis::<N>(i, 1.0), basis::<N>(j, 1.0));
        (t(&(qd + ei + ej)) - t(&(qd + ei - ej)) - t(&(qd - ei + ej)) + t(&(qd - ei - ej))) / 4.0
    });
    worst.close(&m, &hessian, tol, "M = d2T/dqd2");

    // Gravity torques, RNEA at rest and Jacobian against central finite differences of
    // the potential energy and the tip (fourth order: the rounding of V, which grows with
    // the arm's reach, limits a second-order difference's small step).
    let h = 1e-3;
    let fd_tol = 1e-9;
    let at_rest = inverse_dynamics(model, &q, &zero, &zero);
    let mut jac_fd = SMatrix::<f64, 3, N>::zeros();
    for j in 0..N {
        let at = |s: f64| q + basis::<N>(j, s);
        let dv = derivative(
            |s| SMatrix::<f64, 1, 1>::new(potential_energy(model, &at(s))),
            h,
        );
        worst.close_f(grav[j], dv[0], fd_tol, "g = dV/dq");
        worst.close_f(at_rest[j], dv[0], fd_tol, "RNEA(qd = qdd = 0) = dV/dq");
        let column = derivative(
            |s| {
                let tip = tip_position(model, &at(s));
                Vector3::new(tip.x, tip.y, tip_orientation(model, &at(s)))
            },
            h,
        );
        jac_fd.set_column(j, &column);
    }
    worst.close(
        &jacobian(model, &q),
        &jac_fd,
        fd_tol,
        "Jacobian = d tip / dq",
    );

    // The payload handled inside each algorithm against the payload merged into the last
    // link by the parallel-axis theorem.
    let merged = Model::new(model.rigid_links(), 0.0).with_gravity(model.gravity);
    worst.close(&mass_matrix(&merged, &q), &m, tol, "merged M");
    worst.close(
        &inverse_dynamics(&merged, &q, &qd, &qdd),
        &inverse_dynamics(model, &q, &qd, &qdd),
        tol,
        "merged tau",
    );
    worst.close(&gravity_torques(&merged, &q), &grav, tol, "merged g");
    worst.close(&coriolis(&merged, &q, &qd), &cor, tol, "merged c");
    worst.close(
        &forward_dynamics(&merged, &q, &qd, &tau),
        &qdd_aba,
        tol,
        "merged ABA",
    );
    worst.close_f(kinetic_energy(&merged, &q, &qd), t(&qd), tol, "merged T");
    worst.close_f(
        potential_energy(&merged, &q),
        potential_energy(model, &q),
        tol,
        "merged V",
    );

    // Joint 1 at the origin, or slid along +x turned by its offset; the last link runs from
    // the last joint to the tip along the tip orientation, which is the tip angle when no
    // joint slides and none is turned.
    let joints = joint_positions(model, &q);
    let l0 = &model.links[0];
    let first = if slides(l0) {
        let (s, c) = l0.offset.sin_cos();
        let q0 = if l0.reversed { -q[0] } else { q[0] };
        Point2::new(c * q0, s * q0)
    } else {
        Point2::origin()
    };
    worst.close(&joints[0].coords, &first.coords, 1e-15, "joint 1");
    let last_link = tip_position(model, &q) - joints[N - 1];
    let (s, c) = tip_orientation(model, &q).sin_cos();
    worst.close(
        &last_link,
        &(V2::new(c, s) * model.links[N - 1].length),
        1e-12,
        "last link",
    );
    if !model
        .links
        .iter()
        .any(|l| slides(l) || l.offset != 0.0 || l.reversed)
    {
        assert_eq!(tip_orientation(model, &q), tip_angle(&q));
    }
}

/// The arm as a spatial arm in the plane (`to_spatial`: offsets as turns about z, reversed
/// joints about -z or along -x): the spatial reference's Newton-Euler recursion, composite
/// bodies, gravity and kinematics, which share no code with the planar ones.
fn spatial_check<const N: usize>(rng: &mut Rng, model: &Model<N>, worst: &mut Worst) {
    use crate::reference::spatial as sp;
    let spatial = model.to_spatial();
    let q = rng.configuration(model, std::f64::consts::PI);
    let (qd, qdd) = (rng.vector::<N>(3.0), rng.vector::<N>(5.0));
    let tol = 1e-10;
    worst.close(
        &mass_matrix(model, &q),
        &sp::mass_matrix(&spatial, &q),
        tol,
        "M vs spatial",
    );
    worst.close(
        &inverse_dynamics(model, &q, &qd, &qdd),
        &sp::inverse_dynamics(&spatial, &q, &qd, &qdd),
        tol,
        "tau vs spatial",
    );
    worst.close(
        &gravity_torques(model, &q),
        &sp::gravity(&spatial, &q),
        tol,
        "g vs spatial",
    );
    let tip = sp::tip_pose(&spatial, &q);
    worst.close(
        &tip_position(model, &q).coords,
        &tip.translation.vector.xy(),
        tol,
        "tip vs spatial",
    );
    let (s, c) = tip_orientation(model, &q).sin_cos();
    let x = tip.rotation * Vector3::x();
    worst.close(&V2::new(c, s), &x.xy(), tol, "tip orientation vs spatial");
}

/// [`Rng::model`] with every joint's kind, offset (none a third of the time), sense and
/// spring (half of them) random, and gravity in any direction.
fn turned_model<const N: usize>(rng: &mut Rng) -> Model<N> {
    let mut model: Model<N> = rng.mixed_model();
    for link in &mut model.links {
        link.offset = if rng.uniform(0.0, 1.0) < 0.33 {
            0.0
        } else {
            rng.uniform(-3.2, 3.2)
        };
        link.reversed = rng.uniform(0.0, 1.0) < 0.4;
        if rng.uniform(0.0, 1.0) < 0.5 {
            link.stiffness = rng.uniform(0.0, 20.0);
            link.springref = rng.uniform(-1.0, 1.0);
        }
    }
    let g = V2::new(rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0));
    model.with_gravity(g)
}

#[test]
fn turned_and_reversed_joints_cross_check_n1_to_n8() {
    fn one<const N: usize>(rng: &mut Rng, worst: &mut Worst) {
        let model = turned_model::<N>(rng);
        cross_check(rng, &model, worst);
        spatial_check(rng, &model, worst);
    }
    let mut rng = Rng(29);
    let mut worst = Worst::default();
    for _ in 0..100 {
        one::<1>(&mut rng, &mut worst);
        one::<2>(&mut rng, &mut worst);
        one::<3>(&mut rng, &mut worst);
        one::<4>(&mut rng, &mut worst);
        one::<5>(&mut rng, &mut worst);
        one::<6>(&mut rng, &mut worst);
        one::<7>(&mut rng, &mut worst);
        one::<8>(&mut rng, &mut worst);
    }
    worst.print("turned_and_reversed_joints_cross_check_n1_to_n8");
}

/// One random arm of `N` links, all revolute or of mixed joints, for [`cross_check`].
fn cross_check_random<const N: usize>(rng: &mut Rng, mixed: bool, worst: &mut Worst) {
    let model: Model<N> = if mixed {
        rng.mixed_model()
    } else {
        rng.model()
    };
    cross_check(rng, &model, worst);
}

#[test]
fn cross_checks_n1_to_n8() {
    let mut rng = Rng(3);
    let mut worst = Worst::default();
    for _ in 0..200 {
        cross_check_random::<1>(&mut rng, false, &mut worst);
        cross_check_random::<2>(&mut rng, false, &mut worst);
        cross_check_random::<3>(&mut rng, false, &mut worst);
        cross_check_random::<4>(&mut rng, false, &mut worst);
        cross_check_random::<5>(&mut rng, false, &mut worst);
        cross_check_random::<6>(&mut rng, false, &mut worst);
        cross_check_random::<7>(&mut rng, false, &mut worst);
        cross_check_random::<8>(&mut rng, false, &mut worst);
    }
    worst.print("cross_checks_n1_to_n8");
}

#[test]
fn mixed_joint_cross_checks_n1_to_n8() {
    let mut rng = Rng(13);
    let mut worst = Worst::default();
    for _ in 0..200 {
        cross_check_random::<1>(&mut rng, true, &mut worst);
        cross_check_random::<2>(&mut rng, true, &mut worst);
        cross_check_random::<3>(&mut rng, true, &mut worst);
        cross_check_random::<4>(&mut rng, true, &mut worst);
        cross_check_random::<5>(&mut rng, true, &mut worst);
        cross_check_random::<6>(&mut rng, true, &mut worst);
        cross_check_random::<7>(&mut rng, true, &mut worst);
        cross_check_random::<8>(&mut rng, true, &mut worst);
    }
    worst.print("mixed_joint_cross_checks_n1_to_n8");
}

/// Every one of the `2^N` joint patterns of one random arm, all-prismatic chains included.
fn every_pattern<const N: usize>(rng: &mut Rng, worst: &mut Worst) {
    let base: Model<N> = rng.model();
    for pattern in 0..1u32 << N {
        let mut model = base;
        for (i, link) in model.links.iter_mut().enumerate() {
            if pattern >> i & 1 == 1 {
                link.joint = Joint::Prismatic;
            }
        }
        cross_check(rng, &model, worst);
    }
}

#[test]
fn every_joint_pattern_of_1_to_4_links() {
    let mut rng = Rng(14);
    let mut worst = Worst::default();
    for _ in 0..20 {
        every_pattern::<1>(&mut rng, &mut worst);
        every_pattern::<2>(&mut rng, &mut worst);
        every_pattern::<3>(&mut rng, &mut worst);
        every_pattern::<4>(&mut rng, &mut worst);
    }
    worst.print("every_joint_pattern_of_1_to_4_links");
}

/// Armature is a constant on M's diagonal: exactly `A_i` added there and nowhere else,
/// `A_i qdd_i` added to the torque, `A_i qd_i^2 / 2` to the kinetic energy, whatever the
/// joints' kinds (a prismatic joint's armature is a reflected mass).
fn armature_check<const N: usize>(rng: &mut Rng) {
    let model: Model<N> = rng.mixed_model();
    let bare = Model {
        links: model.links.map(|l| l.with_armature(0.0)),
        ..model
    };
    let q = rng.configuration(&model, 4.0);
    let qd = rng.vector::<N>(3.0);
    let qdd = rng.vector::<N>(5.0);
    let (m, m_bare) = (mass_matrix(&model, &q), mass_matrix(&bare, &q));
    let armature = SVector::<f64, N>::from_fn(|i, _| model.links[i].armature);
    for i in 0..N {
        for j in 0..N {
            let expected = if i == j {
                m_bare[(i, j)] + armature[i]
            } else {
                m_bare[(i, j)]
            };
            assert_eq!(m[(i, j)], expected, "M[{i}][{j}]");
        }
    }
    assert_close(
        &(inverse_dynamics(&model, &q, &qd, &qdd) - inverse_dynamics(&bare, &q, &qd, &qdd)),
        &armature.component_mul(&qdd),
        1e-12,
        "armature torque",
    );
    assert_close(
        &(coriolis(&model, &q, &qd) - coriolis(&bare, &q, &qd)),
        &SVector::zeros(),
        0.0,
        "armature leaves c alone",
    );
    assert_close_f(
        kinetic_energy(&model, &q, &qd) - kinetic_energy(&bare, &q, &qd),
        0.5 * armature.dot(&qd.component_mul(&qd)),
        1e-12,
        "armature energy",
    );
}

#[test]
fn armature_is_on_the_diagonal_only() {
    let mut rng = Rng(4);
    for _ in 0..50 {
        armature_check::<1>(&mut rng);
        armature_check::<3>(&mut rng);
        armature_check::<6>(&mut rng);
    }
}

/// A payload against the last link with mass, centre of mass and inertia combined by
/// hand. The rod: 1 m, 2 kg, centre (0.5, 0), inertia 2/12 = 1/6. The payload: 1 kg,
/// inertia 0.05, centre 0.5 beyond the tip and 0.3 to the left, i.e. at (1.5, 0.3) in the
/// link's frame. Together: 3 kg with centre ((2 * 0.5 + 1.5) / 3, 0.3 / 3) = (5/6, 0.1);
/// about it the rod adds 1/6 + 2 ((1/3)^2 + 0.1^2) = 1/6 + 2/9 + 0.02 and the payload
/// 0.05 + 1 ((2/3)^2 + 0.2^2) = 0.05 + 4/9 + 0.04, in all 5/6 + 0.11. (Check: about the
/// joint, 2/3 + 2.39 = 3.0566... = 5/6 + 0.11 + 3 (25/36 + 0.01).)
#[test]
fn payload_is_a_heavier_last_link() {
    let upper = Link::rod(0.8, 1.5).with_com(0.3, 0.05).with_armature(0.02);
    let fore = Link::rod(1.0, 2.0).with_damping(0.1);
    let payload = Payload::point(1.0).with_inertia(0.05).with_com(0.5, 0.3);
    let held = Model::new([upper, fore], 9.81).with_payload(payload);
    let by_hand = Model::new(
        [
            upper,
            Link {
                mass: 3.0,
                com: V2::new(5.0 / 6.0, 0.1),
                inertia: 5.0 / 6.0 + 0.11,
                ..fore
            },
        ],
        9.81,
    );
    let merged = held.rigid_links();
    assert_eq!(merged[0], upper);
    assert_close_f(merged[1].mass, 3.0, 1e-15, "mass");
    assert_close(&merged[1].com, &V2::new(5.0 / 6.0, 0.1), 1e-15, "com");
    assert_close_f(merged[1].inertia, 5.0 / 6.0 + 0.11, 1e-15, "inertia");
    assert_close_f(
        merged[1].inertia_about_joint(),
        2.0 / 3.0 + 2.39,
        1e-15,
        "inertia about the joint",
    );
    assert_eq!(
        (merged[1].length, merged[1].damping),
        (1.0, 0.1),
        "joint parameters kept"
    );

    let mut rng = Rng(5);
    for _ in 0..50 {
        let q = rng.vector::<2>(4.0);
        let qd = rng.vector::<2>(3.0);
        let qdd = rng.vector::<2>(5.0);
        let tol = 1e-13;
        assert_close(
            &mass_matrix(&held, &q),
            &mass_matrix(&by_hand, &q),
            tol,
            "M",
        );
        assert_close(
            &coriolis(&held, &q, &qd),
            &coriolis(&by_hand, &q, &qd),
            tol,
            "c",
        );
        assert_close(
            &gravity_torques(&held, &q),
            &gravity_torques(&by_hand, &q),
            tol,
            "g",
        );
        assert_close(
            &inverse_dynamics(&held, &q, &qd, &qdd),
            &inverse_dynamics(&by_hand, &q, &qd, &qdd),
            tol,
            "tau",
        );
        assert_close(
            &forward_dynamics(&held, &q, &qd, &qdd),
            &forward_dynamics(&by_hand, &q, &qd, &qdd),
            1e-12,
            "ABA",
        );
        assert_close_f(
            kinetic_energy(&held, &q, &qd),
            kinetic_energy(&by_hand, &q, &qd),
            tol,
            "T",
        );
        assert_close_f(
            potential_energy(&held, &q),
            potential_energy(&by_hand, &q),
            tol,
            "V",
        );
    }
    // The tip is the end of the last link, payload or not.
    let q = SVector::from([0.4, -1.0]);
    assert_eq!(tip_position(&held, &q), tip_position(&by_hand, &q));
}

#[test]
fn massless_payload_merges_its_inertia_only() {
    let link = Link::rod(1.0, 0.0).with_inertia(0.0);
    let held = Model::new([link], 0.0).with_payload(Payload::NONE.with_inertia(0.25));
    let [merged] = held.rigid_links();
    assert_eq!(
        (merged.mass, merged.inertia, merged.com),
        (0.0, 0.25, link.com)
    );
    assert_eq!(Model::new([link], 0.0).rigid_links(), [link]);
}
