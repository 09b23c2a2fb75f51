//! The numeric reference for spatial dynamics (`reference::spatial`'s Newton-Euler recursion,
//! Jacobian mass matrix and kinetic energy) against each other, against the gravity torques
//! computed separately, against finite differences of the mass matrix (Christoffel symbols),
//! against conservation of energy, and against cases worked by hand. Random arms of 1 to 7
//! joints in the three conventions, with slides, arbitrary twists, 3-D centres of mass, full
//! inertia tensors, armature and friction.

mod common;

use common::Rng;
use planar_arm::nalgebra::{
    Isometry3, Matrix3, Rotation3, SMatrix, SVector, Translation3, UnitQuaternion, Vector3,
};
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::{JointGeometry, SpatialJoint, SpatialLink, SpatialModel};
use planar_arm::Joint;

/// A random arm: convention `convention` (0 DH, 1 modified DH, 2 URDF), a slide in three.
fn random_arm<const N: usize>(rng: &mut Rng, convention: usize) -> SpatialModel<N> {
    let joints = core::array::from_fn(|_| {
        let mut v = || rng.range(-0.6, 0.6);
        let geometry = match convention {
            0 => JointGeometry::Dh {
                a: v(),
                alpha: 3.0 * v(),
                d: v(),
                theta: 3.0 * v(),
            },
            1 => JointGeometry::Mdh {
                a: v(),
                alpha: 3.0 * v(),
                d: v(),
                theta: 3.0 * v(),
            },
            _ => JointGeometry::Urdf {
                xyz: Vector3::new(v(), v(), v()),
                rpy: Vector3::new(3.0 * v(), 3.0 * v(), 3.0 * v()),
                axis: Vector3::new(v(), v(), v()) + Vector3::new(0.0, 0.0, 0.7),
            },
        };
        let kind = if rng.next() < 0.3 {
            Joint::Prismatic
        } else {
            Joint::Revolute
        };
        SpatialJoint {
            armature: rng.range(0.0, 0.2),
            damping: rng.range(0.0, 0.5),
            frictionloss: rng.range(0.0, 0.3),
            stiffness: rng.range(0.0, 2.0),
            springref: rng.range(-1.0, 1.0),
            ..SpatialJoint::new(geometry, kind)
        }
    });
    let links = core::array::from_fn(|_| {
        // A physical tensor: principal moments meeting the triangle inequality, turned.
        let (a, b, c) = (
            rng.range(0.01, 0.2),
            rng.range(0.01, 0.2),
            rng.range(0.01, 0.2),
        );
        let (x, y, z) = (b + c, a + c, a + b);
        let turn = Rotation3::from_euler_angles(
            rng.range(-3.0, 3.0),
            rng.range(-1.5, 1.5),
            rng.range(-3.0, 3.0),
        );
        let inertia = turn.matrix()
            * Matrix3::from_diagonal(&Vector3::new(x, y, z))
            * turn.matrix().transpose();
        SpatialLink {
            mass: rng.range(0.2, 3.0),
            com: rng.vector(0.3),
            inertia,
        }
    });
    SpatialModel {
        joints,
        links,
        gravity: rng.vector(10.0),
        tool: Isometry3::from_parts(
            Translation3::from(rng.vector::<3>(0.2)),
            UnitQuaternion::identity(),
        ),
        payload: None,
    }
}

fn biggest<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> f64 {
    m.amax().max(1.0)
}

/// Every property of one random arm at `draws` random states.
fn check<const N: usize>(seed: u64, draws: usize) -> (f64, f64, f64, f64) {
    let mut rng = Rng(seed);
    let (mut crba, mut grav, mut energy, mut christoffel) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    for convention in 0..3 {
        let model = random_arm::<N>(&mut rng, convention);
        assert_eq!(model.check(), Ok(()));
        for _ in 0..draws {
            let q: SVector<f64, N> = rng.vector(3.0);
            let qd: SVector<f64, N> = rng.vector(2.0);
            let m = reference::mass_matrix(&model, &q);
            // Newton-Euler at unit accelerations, with no velocity, friction or gravity terms:
            // the columns of M.
            let still =
                reference::inverse_dynamics(&model, &q, &SVector::zeros(), &SVector::zeros());
            let columns = SMatrix::<f64, N, N>::from_fn(|r, c| {
                let e = SVector::<f64, N>::from_fn(|i, _| f64::from(u8::from(i == c)));
                reference::inverse_dynamics(&model, &q, &SVector::zeros(), &e)[r] - still[r]
            });
            crba = crba.max((m - columns).amax() / biggest(&m));
            assert!((m - m.transpose()).amax() <= 1e-14 * biggest(&m));
            assert!(m.cholesky().is_some(), "M not positive definite");
            // At rest, Newton-Euler's forces are the gravity torques (dV/dq by its own sum).
            let g = reference::gravity(&model, &q);
            grav = grav.max((still - g).amax() / biggest(&g));
            // The kinetic energy from the velocity recursion is qd' M qd / 2.
            let t = reference::kinetic_energy(&model, &q, &qd);
            energy = energy.max((t - 0.5 * qd.dot(&(m * qd))).abs() / t.max(1.0));
            // c from Christoffel symbols of M, by central differences of M.
            let h = 1e-5;
            let dm: Vec<SMatrix<f64, N, N>> = (0..N)
                .map(|k| {
                    let mut step = SVector::<f64, N>::zeros();
                    step[k] = h;
                    (reference::mass_matrix(&model, &(q + step))
                        - reference::mass_matrix(&model, &(q - step)))
                        / (2.0 * h)
                })
                .collect();
            let c = reference::coriolis(&model, &q, &qd);
            let from_m = SVector::<f64, N>::from_fn(|i, _| {
                let mut sum = 0.0;
                for j in 0..N {
                    for k in 0..N {
                        sum += (dm[k][(i, j)] - 0.5 * dm[i][(j, k)]) * qd[j] * qd[k];
                    }
                }
                sum
            });
            christoffel = christoffel.max((c - from_m).amax() / biggest(&c));
            // The pieces add up, and forward dynamics undoes inverse dynamics.
            let qdd: SVector<f64, N> = rng.vector(5.0);
            let tau = reference::inverse_dynamics(&model, &q, &qd, &qdd);
            let parts = m * qdd + c + g + reference::friction(&model, &qd);
            assert!(
                (tau - parts).amax() <= 1e-11 * biggest(&tau),
                "{tau} {parts}"
            );
            let back = reference::forward_dynamics(&model, &q, &qd, &tau);
            assert!((back - qdd).amax() <= 1e-8 * biggest(&qdd), "{back} {qdd}");
        }
    }
    (crba, grav, energy, christoffel)
}

#[test]
fn newton_euler_jacobians_energy_and_christoffel_agree() {
    let mut worst = [0.0_f64; 4];
    let mut take = |r: (f64, f64, f64, f64)| {
        for (w, x) in worst.iter_mut().zip([r.0, r.1, r.2, r.3]) {
            *w = w.max(x);
        }
    };
    for seed in 0..6 {
        take(check::<1>(seed, 5));
        take(check::<2>(seed + 10, 5));
        take(check::<3>(seed + 20, 5));
        take(check::<4>(seed + 30, 5));
        take(check::<5>(seed + 40, 5));
        take(check::<6>(seed + 50, 5));
        take(check::<7>(seed + 60, 5));
    }
    eprintln!(
        "worst relative gaps: M against Newton-Euler {:.1e}, gravity {:.1e}, kinetic energy {:.1e}, Christoffel {:.1e}",
        worst[0], worst[1], worst[2], worst[3]
    );
    assert!(worst[0] <= 1e-12, "M against Newton-Euler: {:e}", worst[0]);
    assert!(worst[1] <= 1e-12, "gravity: {:e}", worst[1]);
    assert!(worst[2] <= 1e-12, "kinetic energy: {:e}", worst[2]);
    // Central differences with h = 1e-5: error of order h^2 |M'''| and eps |M| / h.
    assert!(worst[3] <= 1e-7, "Christoffel: {:e}", worst[3]);
}

/// Total energy along a free motion (no friction, no torque), by classical fourth-order
/// Runge-Kutta with small steps: it must stay put to the integrator's error.
#[test]
fn a_free_arm_keeps_its_energy() {
    let mut rng = Rng(99);
    for convention in 0..3 {
        let mut model = random_arm::<5>(&mut rng, convention);
        for j in &mut model.joints {
            j.damping = 0.0;
            j.frictionloss = 0.0;
        }
        let total = |q: &SVector<f64, 5>, qd: &SVector<f64, 5>| {
            reference::kinetic_energy(&model, q, qd) + reference::potential_energy(&model, q)
        };
        let accel = |q: &SVector<f64, 5>, qd: &SVector<f64, 5>| {
            reference::forward_dynamics(&model, q, qd, &SVector::zeros())
        };
        let (mut q, mut qd): (SVector<f64, 5>, SVector<f64, 5>) =
            (rng.vector(2.0), rng.vector(1.0));
        let start = total(&q, &qd);
        let dt = 1e-3;
        let mut worst = 0.0_f64;
        for _ in 0..1000 {
            let (k1q, k1v) = (qd, accel(&q, &qd));
            let (k2q, k2v) = (
                qd + k1v * (dt / 2.0),
                accel(&(q + k1q * (dt / 2.0)), &(qd + k1v * (dt / 2.0))),
            );
            let (k3q, k3v) = (
                qd + k2v * (dt / 2.0),
                accel(&(q + k2q * (dt / 2.0)), &(qd + k2v * (dt / 2.0))),
            );
            let (k4q, k4v) = (qd + k3v * dt, accel(&(q + k3q * dt), &(qd + k3v * dt)));
            q += (k1q + k2q * 2.0 + k3q * 2.0 + k4q) * (dt / 6.0);
            qd += (k1v + k2v * 2.0 + k3v * 2.0 + k4v) * (dt / 6.0);
            worst = worst.max((total(&q, &qd) - start).abs());
        }
        let scale = reference::kinetic_energy(&model, &q, &qd).max(1.0);
        assert!(
            worst <= 1e-7 * scale,
            "convention {convention}: energy drifted by {worst:e} J"
        );
    }
}

/// One hinge about z with its centre of mass `l` out along x and gravity along -y: the
/// textbook pendulum, `M = Izz + m l^2`, `g = m g0 l cos q`, no velocity terms; and one
/// vertical slide under gravity, `tau = m (qdd + g0)`.
#[test]
fn pendulum_and_slide_by_hand() {
    let (m, l, izz, g0) = (1.5, 0.4, 0.02, 9.81);
    let pendulum = SpatialModel::<1> {
        joints: [SpatialJoint::new(
            JointGeometry::Dh {
                a: 0.0,
                alpha: 0.0,
                d: 0.0,
                theta: 0.0,
            },
            Joint::Revolute,
        )],
        links: [SpatialLink {
            mass: m,
            com: Vector3::new(l, 0.0, 0.0),
            inertia: Matrix3::from_diagonal(&Vector3::new(0.01, 0.03, izz)),
        }],
        gravity: Vector3::new(0.0, -g0, 0.0),
        tool: Isometry3::identity(),
        payload: None,
    };
    // The same pendulum as a massless link holding its bob as a payload, at a tool frame out
    // along the link and turned about the joint's axis (the payload's zz stays zz).
    let carried = SpatialModel::<1> {
        links: [SpatialLink::MASSLESS],
        tool: Isometry3::new(Vector3::new(l, 0.0, 0.0), Vector3::new(0.0, 0.0, 0.7)),
        payload: Some(SpatialLink {
            mass: m,
            com: Vector3::zeros(),
            inertia: Matrix3::from_diagonal(&Vector3::new(0.01, 0.03, izz)),
        }),
        ..pendulum
    };
    for (q, qd, qdd) in [(0.3, 2.0, -1.0), (-2.0, -0.5, 4.0), (1.2, 0.0, 0.0)] {
        let want = (izz + m * l * l) * qdd + m * g0 * l * f64::cos(q);
        let (q, qd, qdd) = (
            SVector::from([q]),
            SVector::from([qd]),
            SVector::from([qdd]),
        );
        let tau = reference::inverse_dynamics(&carried, &q, &qd, &qdd)[0];
        assert!((tau - want).abs() < 1e-13, "{tau} {want}");
        let t = reference::kinetic_energy(&carried, &q, &qd);
        assert!((t - 0.5 * (izz + m * l * l) * qd[0] * qd[0]).abs() < 1e-14);
    }
    for (q, qd, qdd) in [(0.3, 2.0, -1.0), (-2.0, -0.5, 4.0), (1.2, 0.0, 0.0)] {
        let tau = reference::inverse_dynamics(
            &pendulum,
            &SVector::from([q]),
            &SVector::from([qd]),
            &SVector::from([qdd]),
        )[0];
        let want = (izz + m * l * l) * qdd + m * g0 * l * f64::cos(q);
        assert!((tau - want).abs() < 1e-13, "{tau} {want}");
        let t = reference::kinetic_energy(&pendulum, &SVector::from([q]), &SVector::from([qd]));
        assert!((t - 0.5 * (izz + m * l * l) * qd * qd).abs() < 1e-14);
    }
    let slide = SpatialModel::<1> {
        joints: [SpatialJoint::new(
            JointGeometry::Urdf {
                xyz: Vector3::zeros(),
                rpy: Vector3::zeros(),
                axis: Vector3::new(0.0, 0.0, 2.0),
            },
            Joint::Prismatic,
        )],
        links: [SpatialLink {
            mass: m,
            com: Vector3::new(0.1, -0.2, 0.3),
            inertia: Matrix3::identity(),
        }],
        gravity: Vector3::new(0.0, 0.0, -g0),
        tool: Isometry3::identity(),
        payload: None,
    };
    let tau = reference::inverse_dynamics(
        &slide,
        &SVector::from([0.7]),
        &SVector::from([3.0]),
        &SVector::from([-2.0]),
    )[0];
    assert!((tau - m * (-2.0 + g0)).abs() < 1e-13, "{tau}");
}

/// Friction is MuJoCo's: viscous plus Coulomb with `sign(0) = 0`.
#[test]
fn friction_terms() {
    let mut rng = Rng(5);
    let model = random_arm::<3>(&mut rng, 0);
    let f = reference::friction(&model, &SVector::from([1.5, 0.0, -2.0]));
    let j = &model.joints;
    assert_eq!(f[0], j[0].damping * 1.5 + j[0].frictionloss);
    assert_eq!(f[1], 0.0);
    assert_eq!(f[2], j[2].damping * -2.0 - j[2].frictionloss);
}

/// A fixture's lines after an `arm` line: key and numbers.
type Lines<'a> = Vec<(&'a str, Vec<f64>)>;

/// Pinocchio 4's `rnea` and `crba` (the fixture `tests/data/pinocchio_spatial_dynamics.txt`,
/// written by `bench/pinocchio/spatial_dynamics.py`): the PUMA 560 and a random seven-joint
/// modified-DH arm with full inertia tensors and armature, five states each.
#[test]
fn pinocchio_agrees() {
    fn numbers(rest: &str) -> Vec<f64> {
        rest.split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect()
    }
    fn compare<const N: usize>(lines: &Lines, modified: bool) -> (f64, f64, usize) {
        let gravity = Vector3::from_column_slice(&lines[0].1);
        let joints = core::array::from_fn(|i| {
            let v = &lines[1 + i].1;
            let (a, alpha, d, theta) = (v[0], v[1], v[2], v[3]);
            let geometry = if modified {
                JointGeometry::Mdh { a, alpha, d, theta }
            } else {
                JointGeometry::Dh { a, alpha, d, theta }
            };
            SpatialJoint {
                armature: v[4],
                ..SpatialJoint::new(geometry, Joint::Revolute)
            }
        });
        let links = core::array::from_fn(|i| {
            let v = &lines[1 + N + i].1;
            SpatialLink {
                mass: v[0],
                com: Vector3::new(v[1], v[2], v[3]),
                inertia: Matrix3::new(v[4], v[7], v[8], v[7], v[5], v[9], v[8], v[9], v[6]),
            }
        });
        let model = SpatialModel::<N> {
            joints,
            links,
            gravity,
            tool: Isometry3::identity(),
            payload: None,
        };
        let (mut tau_gap, mut m_gap, mut states) = (0.0_f64, 0.0_f64, 0);
        for state in lines[1 + 2 * N..].chunks(5) {
            let v = |k: usize| SVector::<f64, N>::from_column_slice(&state[k].1);
            let (q, qd, qdd, tau) = (v(0), v(1), v(2), v(3));
            let m = SMatrix::<f64, N, N>::from_row_slice(&state[4].1);
            let ours = reference::inverse_dynamics(&model, &q, &qd, &qdd);
            tau_gap = tau_gap.max((ours - tau).amax() / biggest(&tau));
            m_gap = m_gap.max((reference::mass_matrix(&model, &q) - m).amax() / biggest(&m));
            states += 1;
        }
        (tau_gap, m_gap, states)
    }
    let text = include_str!("data/pinocchio_spatial_dynamics.txt");
    let mut arms: Vec<(String, Lines)> = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let (key, rest) = line.split_once(' ').unwrap();
        if key == "arm" {
            arms.push((rest.to_string(), Vec::new()));
        } else {
            arms.last_mut().unwrap().1.push((key, numbers(rest)));
        }
    }
    assert_eq!(arms.len(), 2);
    for (header, lines) in &arms {
        let modified = header.contains("mdh");
        let (tau, m, states) = if header.ends_with(" 6") {
            compare::<6>(lines, modified)
        } else {
            compare::<7>(lines, modified)
        };
        eprintln!("{header}: {states} states, tau within {tau:.1e}, M within {m:.1e} (relative)");
        assert_eq!(states, 5);
        assert!(tau <= 1e-12 && m <= 1e-12, "{header}: tau {tau:e}, M {m:e}");
    }
}

/// The regressor times the standard parameters is the rigid bodies' inverse dynamics; with
/// armature and friction added, the whole of it. Each column is checked to be the torques of
/// its parameter alone: doubling one link's parameters doubles that link's share.
#[test]
fn the_regressor_reproduces_the_inverse_dynamics() {
    fn check<const N: usize>(seed: u64) -> f64 {
        let mut rng = Rng(seed);
        let mut worst = 0.0_f64;
        for convention in 0..3 {
            let model = random_arm::<N>(&mut rng, convention);
            let theta = reference::standard_parameters(&model);
            for _ in 0..5 {
                let (q, qd, qdd): (SVector<f64, N>, SVector<f64, N>, SVector<f64, N>) =
                    (rng.vector(3.0), rng.vector(2.0), rng.vector(5.0));
                let blocks = reference::regressor(&model, &q, &qd, &qdd);
                // The joints' own terms, friction and springs, beside the links' blocks.
                let mut tau = reference::friction(&model, &qd) + reference::springs(&model, &q);
                for i in 0..N {
                    tau[i] += model.joints[i].armature * qdd[i];
                }
                for (y, t) in blocks.iter().zip(&theta) {
                    tau += y * t;
                }
                let want = reference::inverse_dynamics(&model, &q, &qd, &qdd);
                worst = worst.max((tau - want).amax() / want.amax().max(1.0));
                // A heavier last link: its block alone accounts for the change.
                let mut heavier = model;
                heavier.links[N - 1].mass *= 2.0;
                heavier.links[N - 1].inertia *= 2.0;
                let change = reference::inverse_dynamics(&heavier, &q, &qd, &qdd) - want;
                let predicted = blocks[N - 1] * theta[N - 1];
                worst = worst.max((change - predicted).amax() / want.amax().max(1.0));
            }
        }
        worst
    }
    let worst = [
        check::<1>(1),
        check::<2>(2),
        check::<4>(4),
        check::<6>(6),
        check::<7>(7),
    ]
    .into_iter()
    .fold(0.0_f64, f64::max);
    eprintln!("regressor against the inverse dynamics: {worst:.1e} relative");
    assert!(worst < 1e-12, "{worst:e}");
}
