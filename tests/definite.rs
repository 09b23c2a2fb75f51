//! `Model::check` refuses exactly the arms whose mass matrix is singular, as the derive does
//! for literal values: run-time values that leave a joint moving nothing are refused, and
//! links that only look degenerate are accepted with finite forward dynamics.

use planar_arm::nalgebra::Vector2;
use planar_arm::prelude::*;
use planar_arm::symbolic::definite::weak_joint;
use planar_arm::symbolic::ring::{parse_decimal, Rational};
use planar_arm::symbolic::{ArmSpec, JointKind, LinkSpec, PayloadSpec};
use planar_arm::{ArmError, Joint, Link, Model, Payload};

/// Two links whose values are read at run time.
#[derive(PlanarArm)]
#[arm(gravity = 9.81)]
struct Tunable {
    #[arm(length = self.l1, mass = 1)]
    upper: Revolute,
    #[arm(length = 0.5, mass = 1, inertia = self.i2, com = (self.c2, 0), armature = self.a2)]
    fore: Revolute,
    l1: f64,
    i2: f64,
    c2: f64,
    a2: f64,
}

/// A cart-pole whose pole length is read at run time.
#[derive(PlanarArm)]
#[arm(gravity = 9.81)]
struct CartPole {
    #[arm(length = 0, mass = 1)]
    cart: Prismatic,
    #[arm(length = self.l, mass = 0.1, inertia = 0.1 * self.l * self.l / 12, com = self.l / 2)]
    pole: Revolute,
    l: f64,
}

fn tunable(l1: f64, i2: f64, c2: f64, a2: f64) -> Tunable {
    Tunable {
        upper: Revolute,
        fore: Revolute,
        l1,
        i2,
        c2,
        a2,
    }
}

fn refused_at(result: Result<(), ArmError>, joint: usize) {
    match result {
        Err(ArmError::OutOfRange {
            what: "mass matrix",
            link: Some(j),
            ..
        }) => assert_eq!(j, joint),
        other => panic!("expected a singular mass matrix at joint {joint}, got {other:?}"),
    }
}

#[test]
fn run_time_values_that_make_m_singular_are_refused() {
    // The case: the last link's mass on its axis, no inertia, no armature.
    let arm = tunable(1.0, 0.0, 0.0, 0.0);
    refused_at(arm.model().check(), 1);
    let qdd: Vector2<f64> = arm.forward_dynamics(
        &Vector2::new(0.3, 0.2),
        &Vector2::zeros(),
        &Vector2::new(1.0, 1.0),
    );
    assert!(
        qdd.iter().any(|x| !x.is_finite()),
        "{qdd}: the refusal is not needed?"
    );
    // Armature keeps it definite: accepted, and the dynamics finite.
    let geared = tunable(1.0, 0.0, 0.0, 0.01);
    assert_eq!(geared.model().check(), Ok(()));
    let qdd: Vector2<f64> = geared.forward_dynamics(
        &Vector2::new(0.3, 0.2),
        &Vector2::zeros(),
        &Vector2::new(1.0, 1.0),
    );
    assert!(qdd.iter().all(|x| x.is_finite()), "{qdd}");
    // A first link of 1e-300 m: the second link turns about (almost) the same axis for both
    // joints.
    refused_at(tunable(1e-300, 0.02, 0.25, 0.0).model().check(), 1);
    // A pole of 1e-300 m: its inertia about the hinge underflows.
    refused_at(
        CartPole {
            cart: Prismatic,
            pole: Revolute,
            l: 1e-300,
        }
        .model()
        .check(),
        1,
    );
    let fine = CartPole {
        cart: Prismatic,
        pole: Revolute,
        l: 0.5,
    };
    assert_eq!(fine.model().check(), Ok(()));
    // The message says what is wrong and where.
    let text = tunable(1.0, 0.0, 0.0, 0.0)
        .model()
        .check()
        .unwrap_err()
        .to_string();
    assert!(
        text.contains("links[1] (the 2nd link)") && text.contains("mass matrix is singular"),
        "{text}"
    );
}

#[test]
fn a_point_cart_and_a_massless_hub_are_accepted() {
    let cart = Model::new(
        [
            Link::rod(0.0, 1.0).with_joint(Joint::Prismatic),
            Link::rod(0.5, 0.1),
        ],
        9.81,
    );
    assert_eq!(cart.check(), Ok(()));
    let hub = Model::new(
        [
            Link::rod(0.3, 2.0).with_inertia(0.0).with_com(0.0, 0.0),
            Link::rod(0.5, 1.0),
        ],
        9.81,
    );
    assert_eq!(hub.check(), Ok(()));
    // A payload beyond a link that carries nothing itself.
    let tip = Model::new(
        [
            Link::rod(1.0, 1.0),
            Link::rod(0.5, 1.0).with_inertia(0.0).with_com(0.0, 0.0),
        ],
        9.81,
    );
    refused_at(tip.check(), 1);
    assert_eq!(tip.with_payload(Payload::point(0.5)).check(), Ok(()));
}

/// Deterministic splitmix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// One of a few values, zero and tiny ones often, so that degenerate arms are common.
    fn value(&mut self) -> (f64, Rational) {
        let text = ["0", "0", "1e-300", "0.25", "1", "0.5", "2"][(self.next() % 7) as usize];
        (text.parse().unwrap(), parse_decimal(text).unwrap())
    }
}

#[test]
fn the_run_time_check_agrees_with_the_derive_s() {
    let mut rng = Rng(41);
    let (mut refused, mut accepted) = (0, 0);
    for _ in 0..3000 {
        let n = 1 + (rng.next() % 4) as usize;
        let mut links = Vec::new();
        let mut specs = Vec::new();
        for _ in 0..n {
            let prismatic = rng.next().is_multiple_of(3);
            let (length, l) = rng.value();
            let (inertia, i) = rng.value();
            let (cx, x) = rng.value();
            let (armature, a) = if rng.next().is_multiple_of(4) {
                rng.value()
            } else {
                (0.0, Rational::from_integer(0.into()))
            };
            links.push(
                Link::rod(length, 1.0)
                    .with_inertia(inertia)
                    .with_com(cx, 0.0)
                    .with_armature(armature)
                    .with_joint(if prismatic {
                        Joint::Prismatic
                    } else {
                        Joint::Revolute
                    }),
            );
            let mut spec = LinkSpec::rod(l, Rational::from_integer(1.into()));
            spec.inertia = i;
            spec.com = (x, Rational::from_integer(0.into()));
            spec.armature = a;
            spec.joint = if prismatic {
                JointKind::Prismatic
            } else {
                JointKind::Revolute
            };
            specs.push(spec);
        }
        let (payload, p) = if rng.next().is_multiple_of(3) {
            (
                Payload::point(0.5),
                Some(PayloadSpec {
                    mass: parse_decimal("0.5").unwrap(),
                    inertia: Rational::from_integer(0.into()),
                    com: (
                        Rational::from_integer(0.into()),
                        Rational::from_integer(0.into()),
                    ),
                }),
            )
        } else {
            (Payload::NONE, None)
        };
        let exact = weak_joint(&ArmSpec {
            links: specs,
            gravity: planar_arm_core::down(Rational::from_integer(0.into())),
            payload: p,
        });
        let numeric = match n {
            1 => check_of::<1>(&links, payload),
            2 => check_of::<2>(&links, payload),
            3 => check_of::<3>(&links, payload),
            _ => check_of::<4>(&links, payload),
        };
        match (exact, numeric) {
            (None, Ok(())) => accepted += 1,
            (
                Some((j, _)),
                Err(ArmError::OutOfRange {
                    what: "mass matrix",
                    link: Some(k),
                    ..
                }),
            ) => {
                assert_eq!(j, k, "{links:?}");
                refused += 1;
            }
            (e, n) => panic!("{links:?} {payload:?}: derive {e:?}, run time {n:?}"),
        }
    }
    assert!(
        refused > 200 && accepted > 1000,
        "{refused} refused, {accepted} accepted"
    );
}

fn check_of<const N: usize>(links: &[Link], payload: Payload) -> Result<(), ArmError> {
    let links: [Link; N] = core::array::from_fn(|k| links[k]);
    Model::new(links, 9.81).with_payload(payload).check()
}
