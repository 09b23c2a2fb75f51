//! No generated path allocates: a counting global allocator around calls of every generated
//! method (and the closed-form inverse kinematics and statics) of a few derived arms.
//!
//! The counter is per thread, so the test harness's own threads cannot disturb it.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;

use planar_arm::prelude::*;
use planar_arm::sim::{
    ComputedTorque, Integrator, PdGravity, Quintic, Rk4, SemiImplicitEuler, Simulator, TipLine,
    Trajectory, Variational4, VariationalMidpoint, ViaPoints,
};

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    // `try_with`: the thread-local may already be gone while a thread shuts down.
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
}

// SAFETY: every call is forwarded unchanged to the system allocator; counting touches only a
// `const`-initialised thread-local `Cell`, which never allocates.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: the caller upholds `GlobalAlloc::alloc`'s contract, passed on unchanged.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: as for `alloc`.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        // SAFETY: as for `alloc`; `ptr` came from this allocator, which is `System`.
        unsafe { System.realloc(ptr, layout, new_size) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` came from this allocator, which is `System`.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// The number of allocations `f` makes on this thread.
fn allocations(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    f();
    ALLOCATIONS.with(Cell::get) - before
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct One {
    #[arm(length = 3/2, mass = 2, inertia = 1/5, com = 3/4)]
    a: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct TwoEqual {
    #[arm(length = 1, mass = 1)]
    a: Revolute,
    #[arm(length = 1, mass = 1)]
    b: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 1.625)]
struct Two {
    #[arm(length = 12/5, mass = 9.60, inertia = 26/97, com = 19/7)]
    a: Revolute,
    #[arm(length = 5/4, mass = 36/5, com = 1/2)]
    b: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Three {
    #[arm(length = 25/6, mass = 3.70)]
    a: Revolute,
    #[arm(length = 3, mass = 35/3, inertia = 37/44, com = -7/3)]
    b: Revolute,
    #[arm(length = 23/6, mass = 7.27, inertia = 1/4, com = 10)]
    c: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 0)]
struct Five {
    #[arm(length = 1/4, mass = 5, inertia = 34/73, com = 0)]
    a: Revolute,
    #[arm(length = 23/5, mass = 4, inertia = 19, com = 15/8)]
    b: Revolute,
    #[arm(length = 15/2, mass = 9.58, com = 12/7)]
    c: Revolute,
    #[arm(length = 2, mass = 5.93, com = -5/3)]
    d: Revolute,
    #[arm(length = 9/2, mass = 25, inertia = 12/7)]
    e: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.80665)]
struct Eight {
    #[arm(length = 9/4, mass = 11/8, inertia = 16/25, com = -9/20)]
    a: Revolute,
    #[arm(length = 3/5, mass = 4/5, inertia = 3/5, com = 3/10)]
    b: Revolute,
    #[arm(length = 9/5, mass = 11/4, inertia = 3/2, com = 54/25)]
    c: Revolute,
    #[arm(length = 14/5, mass = 2, inertia = 21/50, com = 0)]
    d: Revolute,
    #[arm(length = 9/10, mass = 5, inertia = 1/25, com = 27/50)]
    e: Revolute,
    #[arm(length = 4/5, mass = 6/5, inertia = 2/5, com = 24/25)]
    f: Revolute,
    #[arm(length = 3/2, mass = 16/5, inertia = 29/25, com = 0)]
    g: Revolute,
    #[arm(length = 16/5, mass = 33/8, inertia = 3/10, com = 96/25)]
    h: Revolute,
}

use planar_arm::simd::{SimdValue, WideF64x4};

fn vector<const N: usize>(offset: f64) -> SVector<f64, N> {
    #[allow(clippy::cast_precision_loss)]
    SVector::from_fn(|i, _| (offset + 0.7 * i as f64).sin() * 1.3)
}

/// Every method of `PlanarArm` that the derive generates, and the checked wrappers.
fn every_generated_method<A: PlanarArm<N>, const N: usize>(arm: &A) {
    let (q, qd, qdd) = (vector::<N>(0.3), vector::<N>(1.1), vector::<N>(2.2));
    let tau = arm.inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd));
    black_box(tau);
    black_box(arm.mass_matrix(black_box(&q)));
    black_box(arm.coriolis(black_box(&q), black_box(&qd)));
    black_box(arm.coriolis_matrix(black_box(&q), black_box(&qd)));
    black_box(arm.gravity(black_box(&q)));
    black_box(arm.forward_dynamics(black_box(&q), black_box(&qd), black_box(&tau)));
    black_box(arm.kinetic_energy(black_box(&q), black_box(&qd)));
    black_box(arm.potential_energy(black_box(&q)));
    black_box(arm.tip_pose(black_box(&q)));
    black_box(arm.jacobian(black_box(&q)));
    black_box(arm.joint_positions(black_box(&q)));
    black_box(arm.tip_polar(black_box(&q)));
    black_box(arm.joint_torques(black_box(&q), black_box(&Vector2::new(0.5, -2.0)), 0.25));
    black_box(arm.try_inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)))
        .expect("finite");
    black_box(arm.try_forward_dynamics(black_box(&q), black_box(&qd), black_box(&tau)))
        .expect("finite");
    black_box(arm.workspace());
    black_box(arm.manipulability(black_box(&q)));
    black_box(arm.is_singular(black_box(&q), 1e-9));
    let frozen = black_box(arm.freeze());
    black_box(frozen.mass_matrix(black_box(&q)));
    black_box(frozen.bias(black_box(&q), black_box(&qd)));
    black_box(frozen.mass_matrix_and_bias(black_box(&q), black_box(&qd)));
    black_box(frozen.inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)));
    black_box(frozen.forward_dynamics(black_box(&q), black_box(&qd), black_box(&tau)));
}

/// Run-time parameters, a payload, armature and friction: the parameterised code paths.
#[derive(PlanarArm)]
#[arm(gravity = 9.81, payload = self.payload)]
struct Parameterised {
    #[arm(length = 0.35, mass = self.m1, inertia = self.i1, com = self.c1, armature = 0.02, damping = 0.1)]
    a: Revolute,
    #[arm(length = self.l2, mass = 1.2, com = (0.11, 0.005), frictionloss = self.f2)]
    b: Revolute,
    #[arm(length = 0.2, mass = self.m3)]
    c: Revolute,
    m1: f64,
    i1: f64,
    c1: f64,
    l2: f64,
    f2: f64,
    m3: f64,
    payload: f64,
}

impl Default for Parameterised {
    fn default() -> Self {
        Self {
            a: Revolute,
            b: Revolute,
            c: Revolute,
            m1: 2.5,
            i1: 0.03,
            c1: 0.16,
            l2: 0.25,
            f2: 0.3,
            m3: 0.4,
            payload: 0.4,
        }
    }
}

#[track_caller]
fn assert_no_allocation(what: &str, f: impl FnOnce()) {
    let n = allocations(f);
    assert_eq!(n, 0, "{what} allocated {n} times");
}

#[test]
fn the_counter_sees_allocations() {
    assert!(allocations(|| drop(black_box(vec![1u8; 16]))) >= 1);
}

#[test]
fn generated_dynamics_kinematics_and_statics_do_not_allocate() {
    // Touch every arm once first: lazily initialised runtime state (stdout, thread-locals) is
    // not the generated code's.
    let warm = || {
        every_generated_method(&One::default());
        every_generated_method(&TwoEqual::default());
        every_generated_method(&Two::default());
        every_generated_method(&Three::default());
        every_generated_method(&Five::default());
        every_generated_method(&Eight::default());
        every_generated_method(&Parameterised::default());
    };
    warm();
    assert_no_allocation("one link", || every_generated_method(&One::default()));
    assert_no_allocation("two equal links", || {
        every_generated_method(&TwoEqual::default());
    });
    assert_no_allocation("two links", || every_generated_method(&Two::default()));
    assert_no_allocation("three links", || every_generated_method(&Three::default()));
    assert_no_allocation("five links", || every_generated_method(&Five::default()));
    assert_no_allocation("eight links", || every_generated_method(&Eight::default()));
    let three = Three::default();
    let (q, qd, qdd) = (vector::<3>(0.3), vector::<3>(1.1), vector::<3>(2.2));
    let identify = || {
        black_box(three.regressor(black_box(&q), black_box(&qd), black_box(&qdd)));
        black_box(three.standard_parameters());
        black_box(three.base_regressor(black_box(&q), black_box(&qd), black_box(&qdd)));
        black_box(three.base_parameters());
    };
    identify();
    assert_no_allocation("identification", identify);
    assert_no_allocation("run-time parameters", || {
        every_generated_method(&Parameterised::default());
    });
    // The other scalars: f32, and four states in SIMD lanes.
    let arm = Parameterised::default();
    let q32 = SVector::<f32, 3>::new(0.3, -0.4, 0.9);
    let qb = SVector::<WideF64x4, 3>::from_fn(|j, _| WideF64x4::splat(0.3 * j as f64 - 0.2));
    let scalars = || {
        black_box(arm.inverse_dynamics(black_box(&q32), &q32, &q32));
        black_box(arm.forward_dynamics(black_box(&q32), &q32, &q32));
        black_box(arm.mass_matrix_and_bias(black_box(&q32), &q32));
        black_box(arm.freeze().inverse_dynamics(black_box(&q32), &q32, &q32));
        black_box(arm.inverse_dynamics(black_box(&qb), &qb, &qb));
        black_box(arm.forward_dynamics(black_box(&qb), &qb, &qb));
        black_box(arm.mass_matrix_and_bias(black_box(&qb), &qb));
        black_box(arm.freeze().inverse_dynamics(black_box(&qb), &qb, &qb));
    };
    scalars();
    assert_no_allocation("f32 and SIMD batches", scalars);
    // Derivatives and linearisation, what an MPC or iLQR loop calls every step.
    let q = vector::<3>(0.3);
    let derivatives = || {
        black_box(arm.inverse_dynamics_derivatives(black_box(&q), &q, &q));
        black_box(arm.forward_dynamics_derivatives(black_box(&q), &q, &q));
        black_box(arm.linearize(black_box(&q), &q, &q));
        black_box(arm.discretize(black_box(&q), &q, &q, 0.01));
    };
    derivatives();
    assert_no_allocation("derivatives and linearisation", derivatives);
    // A regulator redesigned as the arm moves (gain scheduling).
    let (a, b) = arm.linearize(&q, &q, &q);
    let (ad, bd) = arm.discretize(&q, &q, &q, 0.01);
    let (weight_q, weight_r) = (
        SMatrix::<f64, 6, 6>::identity(),
        SMatrix::<f64, 3, 3>::identity(),
    );
    let regulators = || {
        black_box(planar_arm::lqr(black_box(&a), &b, &weight_q, &weight_r)).expect("stabilisable");
        black_box(planar_arm::dlqr(black_box(&ad), &bd, &weight_q, &weight_r))
            .expect("stabilisable");
    };
    regulators();
    assert_no_allocation("lqr and dlqr", regulators);
}

#[test]
fn closed_form_inverse_kinematics_and_statics_do_not_allocate() {
    let two_equal = TwoEqual::default();
    let two = Two::default();
    let three = Three::default();
    let q2 = vector::<2>(0.4);
    let q3 = vector::<3>(0.4);
    let tau2 = vector::<2>(1.0);
    let tau3 = vector::<3>(1.0);
    let tip2 = two.tip_pose(&q2).translation.vector;
    let tip_equal = two_equal.tip_pose(&q2).translation.vector;
    let pose3 = three.tip_pose(&q3);
    let calls = || {
        black_box(two_equal.inverse_kinematics(black_box(&Point2::from(tip_equal))))
            .expect("reachable");
        black_box(two.inverse_kinematics(black_box(&Point2::from(tip2)))).expect("reachable");
        black_box(three.inverse_kinematics(black_box(&pose3))).expect("reachable");
        black_box(two.tip_force(black_box(&q2), black_box(&tau2))).expect("regular");
        black_box(two_equal.tip_force(black_box(&q2), black_box(&tau2))).expect("regular");
        black_box(three.tip_wrench(black_box(&q3), black_box(&tau3))).expect("regular");
        // The error paths build their errors without allocating too.
        let far = Point2::new(100.0, 0.0);
        assert!(black_box(two.inverse_kinematics(black_box(&far))).is_err());
        let nan = Point2::new(f64::NAN, 0.0);
        assert!(black_box(two_equal.inverse_kinematics(black_box(&nan))).is_err());
        let straight = SVector::<f64, 2>::new(0.3, 0.0);
        assert!(black_box(two.tip_force(black_box(&straight), black_box(&tau2))).is_err());
    };
    calls();
    assert_no_allocation("closed-form inverse kinematics and statics", calls);
}

/// The simulation loop, both controllers, the integrators' steps, a tip-line sample and the
/// step-size bound.
#[test]
fn simulating_does_not_allocate() {
    let arm = TwoEqual::default();
    let path = Quintic::rest_to_rest(Vector2::new(-1.2, 0.3), Vector2::new(0.6, 1.4), 1.0).unwrap();
    let via = ViaPoints::new(
        [0.0, 0.5, 1.0],
        [
            Vector2::new(0.0, 0.5),
            Vector2::new(0.4, 0.9),
            Vector2::new(0.8, 0.2),
        ],
    )
    .unwrap();
    let line = TipLine::new(&arm, Vector2::new(-0.5, 1.5), Point2::new(0.2, 1.4), 1.0).unwrap();
    let n = allocations(|| {
        let sim = Simulator::new(Rk4, 1e-3)
            .unwrap()
            .with_control_period(5e-3)
            .unwrap();
        let ct = ComputedTorque::critically_damped(&arm, path, 20.0);
        for s in sim
            .run(&arm, path.start().q, Vector2::zeros(), 0.2, ct)
            .unwrap()
        {
            black_box(s.unwrap());
        }
        let pd = PdGravity::new(&arm, via, Vector2::new(50.0, 20.0), Vector2::new(5.0, 2.0));
        let sim = Simulator::new(Variational4::default(), 1e-3).unwrap();
        for s in sim
            .run(&arm, Vector2::new(0.0, 0.5), Vector2::zeros(), 0.05, pd)
            .unwrap()
        {
            black_box(s.unwrap());
        }
        let (q, qd, tau) = (
            Vector2::new(0.1, 0.2),
            Vector2::new(0.3, -0.1),
            Vector2::new(1.0, 0.5),
        );
        black_box(SemiImplicitEuler.step(&arm, &q, &qd, &tau, 1e-3).unwrap());
        black_box(
            VariationalMidpoint::default()
                .step(&arm, &q, &qd, &tau, 1e-3)
                .unwrap(),
        );
        black_box(line.sample(0.4));
        black_box(
            planar_arm::sim::fastest_rate(
                &arm,
                &q,
                &Vector2::new(10.0, 5.0),
                &Vector2::new(1.0, 1.0),
            )
            .unwrap(),
        );
    });
    assert_eq!(n, 0, "{n} allocations");
}
