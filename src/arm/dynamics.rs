//! [`Dynamics`]: the equations of motion both derives emit, planar and spatial alike, so that
//! the simulator, the controllers, the linearisation and everything else written over the
//! dynamics take either kind of arm.

use nalgebra::{SMatrix, SVector};

use crate::kinematics::check_vector;
use crate::{mass_inverse, ArmError, Jet, Real};

/// The dynamics of a serial arm of `N` joints, `tau = M(q) qdd + c(q, qd) + g(q) + f(qd)`, as
/// `#[derive(PlanarArm)]` and `#[derive(SpatialArm)]` generate them: `M` the mass matrix (each
/// joint's armature on its diagonal), `c` the velocity-product forces, `g = dV/dq` the gravity
/// forces that hold the arm and `f` the joint friction (MuJoCo's `damping` and `frictionloss`).
/// `q[i]` is joint `i`'s angle (radians) or slide (metres), `tau[i]` its torque or force.
///
/// [`PlanarArm`](crate::PlanarArm) and [`SpatialArm`](crate::spatial::SpatialArm) extend it
/// with each geometry's kinematics and statics; code written over `Dynamics<N>` works for
/// both:
///
/// ```
/// use planar_arm::nalgebra::SVector;
/// use planar_arm::prelude::*;
///
/// /// The torques that hold any arm still at `q`, and the energy it then has.
/// fn hold<A: Dynamics<N>, const N: usize>(arm: &A, q: &SVector<f64, N>) -> (SVector<f64, N>, f64) {
///     let zero = SVector::zeros();
///     (arm.inverse_dynamics(q, &zero, &zero), arm.potential_energy(q))
/// }
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Pendulum {
///     #[arm(length = 1, mass = 1)]
///     link: Revolute,
/// }
///
/// #[derive(SpatialArm, Default)]
/// struct Turntable {
///     #[arm(dh(a = 1, alpha = pi/2), mass = 1, com = (-0.5, 0, 0))]
///     link: Revolute,
/// }
///
/// let (tau, _) = hold(&Pendulum::default(), &SVector::from([0.0]));
/// assert!((tau[0] - 9.81 * 0.5).abs() < 1e-12); // the centre of mass half a metre out
/// let (tau, v) = hold(&Turntable::default(), &SVector::from([0.0]));
/// assert!(tau[0].abs() < 1e-12 && v.abs() < 1e-12); // it turns about the vertical
/// ```
pub trait Dynamics<const N: usize> {
    /// The mass (sensitivity) matrix M(q): symmetric positive definite.
    fn mass_matrix<T: Real>(&self, q: &SVector<T, N>) -> SMatrix<T, N, N>;
    /// The velocity-product (Coriolis and centrifugal) torques c(q, qd).
    fn coriolis<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> SVector<T, N>;
    /// The Coriolis matrix C(q, qd) built from Christoffel symbols: `C qd = c` and `Mdot - 2C` is skew.
    fn coriolis_matrix<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> SMatrix<T, N, N>;
    /// The static torques that hold the arm still, g(q) = dV/dq: against gravity and, for a
    /// spatial arm with joint springs, against them (`stiffness (q - springref)`, whose energy
    /// is part of V).
    fn gravity<T: Real>(&self, q: &SVector<T, N>) -> SVector<T, N>;
    /// The joint friction torques f(qd): viscous `damping qd_i` plus Coulomb
    /// `frictionloss sign(qd_i)` (MuJoCo's `damping` and `frictionloss`), with `sign(0) = 0`.
    /// The Coulomb term is discontinuous at `qd_i = 0`; an integrator stepping through zero
    /// rate chatters around it (a stiction model is not part of this crate).
    fn friction<T: Real>(&self, qd: &SVector<T, N>) -> SVector<T, N>;
    /// The bias h(q, qd) = c + g + f: every torque but the inertial one, so that
    /// `inverse_dynamics(q, qd, qdd) = mass_matrix(q) * qdd + bias(q, qd)` (Pinocchio's
    /// `nonLinearEffects`; MuJoCo's `qfrc_bias` with the passive joint friction added).
    fn bias<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> SVector<T, N>;
    /// `(mass_matrix(q), bias(q, qd))` in one pass that shares the trigonometry and common
    /// subexpressions: what a computed-torque or operational-space controller needs every cycle.
    fn mass_matrix_and_bias<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> (SMatrix<T, N, N>, SVector<T, N>);
    /// [`mass_matrix_and_bias`](Self::mass_matrix_and_bias)'s body, which the derive emits
    /// here and the method calls: inlined, it is compiled into the callers that are compiled
    /// for other target features (the AVX2 copy of the forward dynamics' derivatives), where a
    /// call would run the baseline code.
    #[doc(hidden)]
    #[inline(always)]
    fn __mass_matrix_and_bias_body<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> (SMatrix<T, N, N>, SVector<T, N>) {
        self.mass_matrix_and_bias(q, qd)
    }
    /// The joint torques tau = M qdd + c + g + f.
    fn inverse_dynamics<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        qdd: &SVector<T, N>,
    ) -> SVector<T, N>;
    /// The joint accelerations qdd that solve M qdd = tau - c - g - f.
    ///
    /// With one joint, or two whose mass matrix has no run-time parameter, in closed form
    /// (Cramer's rule, on the exact determinant) on M, c and g as
    /// [`mass_matrix`](Self::mass_matrix), [`coriolis`](Self::coriolis) and
    /// [`gravity`](Self::gravity) return them; otherwise (from three joints, and two with
    /// parameters in M, whose determinant, a product of two of them, could overflow) M and
    /// h = c + g + f as
    /// [`mass_matrix_and_bias`](Self::mass_matrix_and_bias) returns them, solved by an
    /// `L D L^T` factorisation whose pivots are floored at 2^-52 times a bound on `M_ii`, so an
    /// ill-conditioned M gives finite accelerations. The method's docs on your arm give its
    /// operation count.
    fn forward_dynamics<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        tau: &SVector<T, N>,
    ) -> SVector<T, N>;
    /// The partial derivatives of [`inverse_dynamics`](Self::inverse_dynamics),
    /// `(dtau/dq, dtau/dqd)`, N x N each (`dtau/dqdd` is [`mass_matrix`](Self::mass_matrix)),
    /// as Pinocchio's `computeRNEADerivatives`.
    ///
    /// Exact to rounding. For arms whose derivative program stays small (about 4,000
    /// operations, every arm up to 10 links at least) the derive emits it: the inverse dynamics'
    /// straight-line program differentiated at compile time, its operation count in the
    /// method's docs. For larger arms this default evaluates the generated inverse dynamics in
    /// [`Jet<N>`](Jet) ([`Jet::inverse_dynamics_derivatives`]). Run-time parameters, armature,
    /// damping and payload are included. Coulomb friction `frictionloss sign(qd_i)` jumps at
    /// `qd_i = 0` and has no derivative there; it contributes 0 to `dtau/dqd` everywhere (its
    /// derivative away from the jump).
    ///
    /// In a build without debug assertions (Cargo's `release` profile) on x86-64 with `std`,
    /// the emitted program (and [`forward_dynamics_derivatives`](Self::forward_dynamics_derivatives))
    /// runs in a second copy compiled for AVX2 and FMA where the processor has them, chosen at
    /// run time: 1.9-2.8x faster for the PUMA 560 in the benchmarks (docs/performance.md), and
    /// the same result to the bit (Rust fuses no multiply-add it is not asked to;
    /// `tests/dispatch.rs`). For spatial arms that copy runs a second emitted program, the same
    /// chain rule applied four directions at a time in AVX2 registers, its products fused into
    /// multiply-adds (its four-lane operation count is in the method's docs), which agrees with
    /// the first to rounding and was another 1.6-3.6x faster for the PUMA 560 and the Panda.
    fn inverse_dynamics_derivatives(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        self.__inverse_dynamics_derivatives_kernel(q, qd, qdd)
    }
    /// The body of [`inverse_dynamics_derivatives`](Self::inverse_dynamics_derivatives): these
    /// jets, or the program the derive emits, which the emitted method runs through
    /// `__private::dispatch` (the AVX2 copy where the processor has AVX2 and FMA).
    #[doc(hidden)]
    fn __inverse_dynamics_derivatives_kernel(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        Jet::inverse_dynamics_derivatives(self, q, qd, qdd)
    }
    /// The same derivatives computed four directions at a time in `lanes` (see
    /// `src/lanes.rs`), which the dispatch runs where the lanes are registers: the packed
    /// program the derive emits for spatial arms, or else the body above.
    #[doc(hidden)]
    #[inline(always)]
    fn __inverse_dynamics_derivatives_packed<L: crate::__private::Lanes>(
        &self,
        _lanes: L,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        self.__inverse_dynamics_derivatives_kernel(q, qd, qdd)
    }

    /// The partial derivatives of [`forward_dynamics`](Self::forward_dynamics),
    /// `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, N x N each, as Pinocchio's `computeABADerivatives`:
    /// with `qdd = forward_dynamics(q, qd, tau)`, `dqdd/dq = -M^-1 dtau/dq`,
    /// `dqdd/dqd = -M^-1 dtau/dqd` (from [`inverse_dynamics_derivatives`](Self::inverse_dynamics_derivatives)
    /// at `qdd`) and `dqdd/dtau = M^-1`. Coulomb friction as there.
    ///
    /// For planar arms of up to five links the derive emits this as one straight-line program
    /// that shares the trigonometry, M and its factorisation (guarded by the pivot floors of
    /// `forward_dynamics`, so finite wherever `forward_dynamics` is); its operation count is in
    /// the method's docs. Otherwise this default computes it from
    /// [`mass_matrix_and_bias`](Self::mass_matrix_and_bias), one fixed-size `L D L^T`
    /// factorisation of M that gives both `qdd` and `M^-1`, and the inverse dynamics'
    /// derivatives at that `qdd` multiplied by `-M^-1` (no allocation, and none of the emitted
    /// program's compile time; docs/performance.md measures both), NaN everywhere if the
    /// factorisation fails (only with NaN or infinite input). A spatial arm's derive replaces
    /// the derivatives and the products, in optimised x86-64 builds, by one program that runs
    /// the inverse dynamics backward from the torques weighted by the rows of `-M^-1`, eight
    /// rows to an AVX-512 register where the processor has AVX-512 (or two AVX2 registers
    /// where it has AVX2 and FMA): the same to rounding (`tests/dispatch.rs`). NaN input gives
    /// NaN output either way, never a panic.
    fn forward_dynamics_derivatives(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        crate::dispatch::dispatch(crate::dispatch::ForwardDynamicsDerivatives {
            arm: self,
            q,
            qd,
            tau,
        })
    }
    /// The body of [`forward_dynamics_derivatives`](Self::forward_dynamics_derivatives), run
    /// through `__private::dispatch` (the AVX2 copy where the processor has AVX2 and FMA): this
    /// default, or the program the derive emits.
    #[doc(hidden)]
    #[inline(always)]
    fn __forward_dynamics_derivatives_kernel(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        mass_inverse::forward_derivatives(self, self.mass_matrix_and_bias(q, qd), q, qd, tau)
    }

    /// The forward derivatives in `lanes`: the body above, whose inverse derivatives are
    /// dispatched on their own. A spatial arm's derive overrides it with the same computation
    /// from `__mass_matrix_and_bias_body`, so that the AVX2 copy computes M and h in AVX2 code
    /// rather than calling the baseline's (the baseline copy keeps the call).
    #[doc(hidden)]
    #[inline(always)]
    fn __forward_dynamics_derivatives_packed<L: crate::__private::Lanes>(
        &self,
        _lanes: L,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        self.__forward_dynamics_derivatives_kernel(q, qd, tau)
    }

    /// `(-M^-1 dtau/dq, -M^-1 dtau/dqd)` at `(q, qd, qdd)` given `minv = M^-1`, in `lanes`:
    /// the program a spatial arm's derive emits, which runs the inverse dynamics backward from
    /// the torques weighted by the rows of `-M^-1` and gives the products directly
    /// (`programs::adjoint` in the engine; docs/performance.md, "Eighth session"), and which
    /// the derive's forward derivatives call. Where an arm has no such program, this default
    /// gives the same from the inverse derivatives (`tests/dispatch.rs` checks both); the
    /// crate's own forward derivatives then take the default route, which dispatches the
    /// inverse derivatives on their own.
    #[doc(hidden)]
    #[inline(always)]
    fn __forward_dynamics_derivatives_adjoint<L: crate::__private::Lanes>(
        &self,
        lanes: L,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
        minv: &SMatrix<f64, N, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        let (dq, dqd) = self.__inverse_dynamics_derivatives_packed(lanes, q, qd, qdd);
        (
            mass_inverse::minus_product(minv, &dq),
            mass_inverse::minus_product(minv, &dqd),
        )
    }

    /// Kinetic energy, J: the links, the payload and the rotors (`armature qd_i^2 / 2`).
    fn kinetic_energy<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> T;
    /// Potential energy, J: gravity's, measured from the base's origin, and any joint
    /// springs' `stiffness (q - springref)^2 / 2`.
    fn potential_energy<T: Real>(&self, q: &SVector<T, N>) -> T;

    /// A view that evaluates the parameter-only part of the dynamics once and reuses it on every
    /// call, for an arm with run-time parameters whose values hold still for many calls (a
    /// control loop between payload changes). The arm stays borrowed while the view lives, so
    /// its values cannot go stale. See [`Frozen`](crate::Frozen).
    fn freeze(&self) -> crate::Frozen<'_, Self, N> {
        crate::Frozen::new(self)
    }

    /// The parameter-only values [`Frozen`](crate::Frozen) holds (empty for all-literal arms).
    #[doc(hidden)]
    type __Frozen: Copy + Default + core::fmt::Debug;
    #[doc(hidden)]
    fn __freeze(&self) -> Self::__Frozen {
        Self::__Frozen::default()
    }
    #[doc(hidden)]
    fn __mass_matrix_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
    ) -> SMatrix<T, N, N> {
        self.mass_matrix(q)
    }
    #[doc(hidden)]
    fn __bias_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> SVector<T, N> {
        self.bias(q, qd)
    }
    #[doc(hidden)]
    fn __mass_matrix_and_bias_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> (SMatrix<T, N, N>, SVector<T, N>) {
        self.mass_matrix_and_bias(q, qd)
    }
    #[doc(hidden)]
    fn __inverse_dynamics_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        qdd: &SVector<T, N>,
    ) -> SVector<T, N> {
        self.inverse_dynamics(q, qd, qdd)
    }
    #[doc(hidden)]
    fn __forward_dynamics_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        tau: &SVector<T, N>,
    ) -> SVector<T, N> {
        self.forward_dynamics(q, qd, tau)
    }

    /// [`forward_dynamics`](Self::forward_dynamics) for input that may be bad: NaN or infinite
    /// states give an `Err` instead of NaN accelerations.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] naming the first argument that holds NaN or an infinity, or
    /// `"result"` when finite input overflowed.
    fn try_forward_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> Result<SVector<f64, N>, ArmError> {
        check_vector(q, "q")?;
        check_vector(qd, "qd")?;
        check_vector(tau, "tau")?;
        let qdd = self.forward_dynamics(q, qd, tau);
        check_vector(&qdd, "result")?;
        Ok(qdd)
    }

    /// [`inverse_dynamics`](Self::inverse_dynamics) for input that may be bad.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] as for [`try_forward_dynamics`](Self::try_forward_dynamics).
    fn try_inverse_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> Result<SVector<f64, N>, ArmError> {
        check_vector(q, "q")?;
        check_vector(qd, "qd")?;
        check_vector(qdd, "qdd")?;
        let tau = self.inverse_dynamics(q, qd, qdd);
        check_vector(&tau, "result")?;
        Ok(tau)
    }
}
